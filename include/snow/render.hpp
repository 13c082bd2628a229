/// @file render.hpp
/// @brief The OpenGL 3.3 renderer (target snow::render): GL contexts (OSMesa
/// or EGL headless, a GLFW window) from make_context, and a Renderer that
/// draws a Simulation's World and a scene's SceneVisuals from a ViewCamera.
/// GL itself stays private: no GL header is included. See docs/rendering.md.
#pragma once

#include "render/camera.hpp"
#include "render/context/gl_context.hpp"
#include "render/context/glfw_context.hpp"
#include "render/context/make_context.hpp"
#include "render/context/osmesa_context.hpp"
#include "render/image.hpp"
#include "render/render_error.hpp"
#include "render/renderer.hpp"
#include "render/scene_visuals.hpp"

#include <snow/snow.hpp>
