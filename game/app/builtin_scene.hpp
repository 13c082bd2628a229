/// @file builtin_scene.hpp
/// @brief The village scene compiled into the apps, so snow_run and snow_game
/// work with no asset path. Generated from assets/scenes/village.gltf.
#pragma once

#include <string_view>

namespace snow {

/// The text of assets/scenes/village.gltf as it was at build time.
[[nodiscard]] std::string_view builtin_village_gltf();

} // namespace snow
