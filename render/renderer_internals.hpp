/// @file renderer_internals.hpp
/// @brief What the public Renderer (<snow/render.hpp>) hides, for snow's own
/// code only (never installed): drawing a bare World (render tests build
/// one without a Simulation) and inserting extra passes.
#pragma once

#include "ecs/world.hpp"
#include "render/passes/render_pass.hpp"

#include <memory>
#include <string_view>

#include <snow/render.hpp>

namespace snow {

/// Renderer::render of a World: what it draws from a Simulation.
void render_world(Renderer& renderer, const World& world, const SceneVisuals& visuals,
                  const ViewCamera& camera);

/// Inserts `pass` before the pass named `before`; an empty name appends.
/// Throws RenderError for an unknown name or a null pass.
void insert_pass(Renderer& renderer, std::string_view before, std::unique_ptr<RenderPass> pass);

} // namespace snow
