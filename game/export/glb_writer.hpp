/// @file glb_writer.hpp
/// @brief Named triangle meshes as one glTF 2.0 binary (.glb): a node per
/// mesh, one snow material, positions with min/max, unit normals, 32-bit
/// indices, every bufferView 4-byte aligned.
#pragma once

#include "game/export/snow_mesh.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

struct NamedMesh {
    std::string name;
    const SnowMesh* mesh = nullptr; ///< without triangles it is left out
};

/// The bytes of a .glb holding `meshes` (in order), a node each, in one scene.
[[nodiscard]] std::vector<std::uint8_t> encode_glb(const std::vector<NamedMesh>& meshes,
                                                   std::string_view generator);

} // namespace snow
