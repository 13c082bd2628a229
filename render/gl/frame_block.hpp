/// @file frame_block.hpp
/// @brief The per-frame uniform block "Frame" shared by every program; the
/// std140 mirror of the block at the top of assets/shaders/common.glsl.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

namespace snow {

/// Most point lights a frame uses (the first ones in the world's order).
inline constexpr int max_point_lights = 8;

/// Sun shadow cascades in the block (render/passes/sun_cascades.hpp).
inline constexpr int frame_sun_cascades = 3;

/// Only vec4/mat4 members, so the C++ layout equals std140 without padding.
struct FrameBlock {
    glm::mat4 view_proj{1.0f};
    glm::mat4 inv_view_proj{1.0f};
    glm::vec4 camera_pos{0.0f};
    glm::vec4 lens{0.0f};
    glm::vec4 ambient{0.0f};
    glm::vec4 sky{0.0f};
    glm::vec4 sun{0.0f};
    glm::vec4 snow_color{0.0f};
    glm::vec4 fog_color{0.0f};
    glm::vec4 fog_layer{0.0f};
    glm::vec4 occlusion{0.0f};
    glm::vec4 occlusion_shear{0.0f};
    glm::vec4 flake{0.0f};
    glm::vec4 light_params{0.0f};
    glm::vec4 sun_color{0.0f};     ///< rgb: colour × intensity of a Sun, w: exposure
    glm::vec4 view_forward{0.0f};  ///< xyz: the camera's forward axis (cascade choice)
    glm::vec4 cascade_far{0.0f};   ///< xyz: view depth where each cascade ends
    glm::vec4 cascade_texel{0.0f}; ///< xyz: metres per shadow texel, w: 1 / cascade texels
    glm::vec4 snow_detail{0.0f};   ///< x: detail normals, y: sparkle (1 on, 0 off)
    glm::ivec4 counts{0};          ///< w: RenderOutput
    glm::vec4 light_pos[max_point_lights]{};
    glm::vec4 light_color[max_point_lights]{};
    glm::mat4 sun_atlas[frame_sun_cascades]{}; ///< world → (u, v, depth) of the shadow atlas
};
static_assert(sizeof(FrameBlock) ==
                  (2 + frame_sun_cascades) * 64 + 18 * 16 + 2 * max_point_lights * 16,
              "FrameBlock must match the std140 layout of common.glsl");

} // namespace snow
