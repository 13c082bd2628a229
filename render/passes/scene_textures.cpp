#include "render/passes/scene_textures.hpp"

#include "render/passes/fog_table.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

namespace {
void nearest_clamped(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}
} // namespace

bool OcclusionTexture::update(const OcclusionMap& map) {
    if (map.version == version_ && map.width == width_ && map.height == height_) {
        return false;
    }
    version_ = map.version;
    width_ = map.width;
    height_ = map.height;
    const std::size_t n = static_cast<std::size_t>(map.width) * map.height;
    staging_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        // −inf (nothing above) becomes a very low finite height for the shader compare.
        const float y = i < map.top_y.size() ? map.top_y[i] : -1e30f;
        staging_[i] = std::isfinite(y) ? y : -1e30f;
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    nearest_clamped(GL_TEXTURE_2D);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, static_cast<GLsizei>(map.width),
                 static_cast<GLsizei>(map.height), 0, GL_RED, GL_FLOAT, staging_.data());
    return true;
}

void OcclusionTexture::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_2D, texture_.id());
}

bool FogTableTexture::update(const Fog& fog) {
    if (built_ && fog.layer_bottom == bottom_ && fog.layer_top == top_ &&
        fog.layer_density == density_) {
        return false;
    }
    built_ = true;
    bottom_ = fog.layer_bottom;
    top_ = fog.layer_top;
    density_ = fog.layer_density;
    std::vector<glm::vec2> table = layered_fog_table(fog, fog_table_size);
    table.resize(fog_table_size, glm::vec2(0.0f)); // an empty layer: no fog anywhere
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_1D, texture_.id());
    nearest_clamped(GL_TEXTURE_1D);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RG32F, static_cast<GLsizei>(fog_table_size), 0, GL_RG,
                 GL_FLOAT, table.data());
    return true;
}

void FogTableTexture::bind(int unit) const {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    glBindTexture(GL_TEXTURE_1D, texture_.id());
}

} // namespace snow
