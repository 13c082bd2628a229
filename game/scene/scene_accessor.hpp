/// @file scene_accessor.hpp
/// @brief Reads glTF accessors after checking every range ourselves: index,
/// bufferView, buffer, component type, count, stride and offsets against the
/// bytes actually loaded (internal to snow::scene; the cgltf/OSS-Fuzz habit).
#pragma once

#include "game/scene/scene_document.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace snow {

/// Most elements one accessor may hold.
inline constexpr std::size_t max_accessor_count = 1u << 24;

/// The bytes of bufferView `view` (its buffer loaded), every range checked;
/// `field` names the referring property. Throws SceneError.
[[nodiscard]] std::span<const unsigned char>
buffer_view_bytes(const GltfDocument& doc, std::uint64_t view, const std::string& field);

/// Accessor `index` as finite float VEC3 values (POSITION, NORMAL).
/// `field` names the referring property in errors. Throws SceneError.
[[nodiscard]] std::vector<glm::vec3>
read_vec3_accessor(const GltfDocument& doc, std::uint64_t index, const std::string& field);

/// Accessor `index` as finite float VEC2 values (TEXCOORD_0).
[[nodiscard]] std::vector<glm::vec2>
read_vec2_accessor(const GltfDocument& doc, std::uint64_t index, const std::string& field);

/// Accessor `index` as unsigned SCALAR values of 8, 16 or 32 bits (triangle indices).
[[nodiscard]] std::vector<std::uint32_t>
read_index_accessor(const GltfDocument& doc, std::uint64_t index, const std::string& field);

} // namespace snow
