/// @file scene.hpp
/// @brief Scene loading (target snow::scene, no GL): load_scene_file and
/// load_scene_memory turn a glTF 2.0 file whose `extras.snow` objects declare
/// surfaces, colliders and effects into a Simulation and its SceneVisuals
/// (meshes, lights, camera, sky), with SceneOverrides for command-line
/// settings. See docs/scenes.md and docs/embedding.md.
#pragma once

#include "game/scene_loader.hpp"

#include <snow/snow.hpp>
