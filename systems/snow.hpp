/// @file snow.hpp
/// @brief The public header for embedders: `#include <snow/snow.hpp>` and link
/// snow::sim. Create a Simulation (from code, or from a glTF file with
/// snow::scene), step it at a fixed dt, read flakes, surfaces, the state hash
/// and the mass report. No GL is needed. See docs/embedding.md.
#pragma once

#include "systems/colliders.hpp"
#include "systems/emitter.hpp"
#include "systems/flake_pool.hpp"
#include "systems/fog.hpp"
#include "systems/mass_ledger.hpp"
#include "systems/occlusion.hpp"
#include "systems/sample_scenes.hpp"
#include "systems/sim_config.hpp"
#include "systems/simulation.hpp"
#include "systems/snow_surface.hpp"
#include "systems/units.hpp"
#include "systems/wind.hpp"
