#include "render/passes/sun_cascades.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// [PSSM]'s practical split: a blend of the logarithmic split (even texels
/// per pixel) and the uniform one (no slice too thin near the eye).
constexpr float split_blend = 0.75f;

/// View depth of the end of slice i of n between near and far.
float split_depth(int i, int n, float near_plane, float far_plane) {
    const float t = static_cast<float>(i) / static_cast<float>(n);
    const float logarithmic = near_plane * std::pow(far_plane / near_plane, t);
    const float uniform = near_plane + (far_plane - near_plane) * t;
    return split_blend * logarithmic + (1.0f - split_blend) * uniform;
}

} // namespace

SunCascades fit_sun_cascades(const ViewCamera& camera, float aspect, const glm::vec3& to_sun,
                             float distance, int resolution) {
    const glm::vec3 forward = camera.forward();
    const float tan_y = std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
    const float tan_x = tan_y * aspect;
    const float near_plane = camera.near_plane;
    const float far_plane = std::clamp(distance, near_plane * 2.0f, camera.far_plane);

    // One rotation for every cascade and frame: the sun's view turns only with the sun.
    const glm::vec3 l = glm::normalize(to_sun);
    const glm::vec3 helper = std::abs(l.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    const glm::mat4 rotation = glm::lookAt(glm::vec3(0.0f), -l, helper);

    SunCascades c;
    const float res = static_cast<float>(resolution);
    for (int i = 0; i < sun_cascade_count; ++i) {
        const float d0 = split_depth(i, sun_cascade_count, near_plane, far_plane);
        const float d1 = split_depth(i + 1, sun_cascade_count, near_plane, far_plane);
        // The slice's bounding sphere: its centre on the view axis and its
        // radius depend on the lens only, so turning the camera never
        // resizes the cascade (the texels keep their size) [MSDN-SM].
        const float a0 = d0 * d0 * (tan_x * tan_x + tan_y * tan_y);
        const float a1 = d1 * d1 * (tan_x * tan_x + tan_y * tan_y);
        // Centre at depth m on the axis, equally far from both slices' corners.
        const float m = std::min(d1, ((d1 * d1 + a1) - (d0 * d0 + a0)) / (2.0f * (d1 - d0)));
        const float radius = std::sqrt((d1 - m) * (d1 - m) + a1);
        const glm::vec3 centre = camera.position + forward * m;

        // Snap the centre to whole texels of the sun's view: the camera
        // moving then shifts the map by whole texels, and shadow edges do
        // not crawl [MSDN-SM].
        const float texel = 2.0f * radius / res;
        glm::vec3 lc = glm::vec3(rotation * glm::vec4(centre, 1.0f));
        lc.x = std::floor(lc.x / texel) * texel;
        lc.y = std::floor(lc.y / texel) * texel;
        // The sun's view looks down −z: casters up to sun_caster_reach
        // beyond the sphere towards the sun are kept.
        const glm::mat4 ortho =
            glm::ortho(lc.x - radius, lc.x + radius, lc.y - radius, lc.y + radius,
                       -(lc.z + radius + sun_caster_reach), -(lc.z - radius));
        c.light_clip[i] = ortho * rotation;
        // Clip space [−1, 1] → the cascade's third of the atlas and depth [0, 1].
        const float third = 1.0f / static_cast<float>(sun_cascade_count);
        glm::mat4 to_tile(1.0f);
        to_tile[0][0] = 0.5f * third;
        to_tile[1][1] = 0.5f;
        to_tile[2][2] = 0.5f;
        to_tile[3] = glm::vec4((static_cast<float>(i) + 0.5f) * third, 0.5f, 0.5f, 1.0f);
        c.to_atlas[i] = to_tile * c.light_clip[i];
        c.far[i] = d1;
        c.texel[i] = texel;
    }
    return c;
}

} // namespace snow
