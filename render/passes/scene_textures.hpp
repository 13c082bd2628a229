/// @file scene_textures.hpp
/// @brief Textures every pass may sample, re-uploaded only when their source
/// changes: the sky occlusion map [SKY] and the layered-fog table [PE].
#pragma once

#include "render/gl/gl_objects.hpp"
#include "systems/sky/occlusion.hpp"
#include <snow/render.hpp>

#include <cstdint>
#include <vector>

namespace snow {

/// OcclusionMap::top_y as an R32F texture (nearest texels, no filtering).
class OcclusionTexture {
  public:
    /// Uploads when the map's version or size changed; returns true if it did.
    bool update(const OcclusionMap& map);
    void bind(int unit) const;

  private:
    GlTexture texture_;
    std::uint64_t version_ = ~0ull;
    std::uint32_t width_ = 0, height_ = 0;
    std::vector<float> staging_;
};

/// The layered fog's (E(y), density(y)) table as an RG32F 1-D texture.
class FogTableTexture {
  public:
    /// Rebuilds when the layer settings changed; returns true if it did.
    bool update(const Fog& fog);
    void bind(int unit) const;

  private:
    GlTexture texture_;
    bool built_ = false;
    float bottom_ = 0.0f, top_ = 0.0f, density_ = 0.0f;
};

} // namespace snow
