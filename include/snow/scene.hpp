/// @file scene.hpp
/// @brief Scene loading (target snow::scene, no GL): load_scene_file and
/// load_scene_memory turn a glTF 2.0 file (.gltf or .glb) whose `extras.snow`
/// objects declare surfaces, colliders, moving bodies, a cover and effects
/// (or, with auto snow, a plain model's meshes imply them) into a Simulation
/// and its SceneVisuals (meshes, lights, camera, sky), with SceneOverrides for
/// command-line settings. See docs/scenes.md and
/// docs/embedding.md.
#pragma once

#include "game/scene/scene_loader.hpp"

#include <snow/snow.hpp>
