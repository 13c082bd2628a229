#include "render/passes/wind_arrows.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace snow {

namespace {

/// Cells of an axis of n that carry arrows: at most `most`, evenly spread.
std::uint32_t arrow_count(std::uint32_t n, std::uint32_t most) {
    return std::min(n, most);
}

/// World coordinate of the q-th of m arrows along axis a of the field: the
/// centre of the cell at (q + 0.5)·n/m.
float arrow_at(const WindField& f, int a, std::uint32_t q, std::uint32_t m) {
    const auto cell = static_cast<std::uint32_t>((static_cast<double>(q) + 0.5) * f.n[a] / m);
    return f.origin[a] + (static_cast<float>(cell) + 0.5f) / f.inv_cell[a];
}

void add_segment(std::vector<float>& v, const glm::vec3& a, const glm::vec3& b,
                 const glm::vec3& color) {
    for (const glm::vec3& p : {a, b}) {
        v.insert(v.end(), {p.x, p.y, p.z, color.r, color.g, color.b});
    }
}

} // namespace

glm::vec3 wind_speed_color(float share) {
    static constexpr std::array<glm::vec3, 4> ramp{{
        {0.15f, 0.3f, 1.0f}, // still
        {0.1f, 0.85f, 0.3f},
        {1.0f, 0.9f, 0.1f},
        {1.0f, 0.15f, 0.1f}, // fastest
    }};
    const float t = std::clamp(share, 0.0f, 1.0f) * static_cast<float>(ramp.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(t), ramp.size() - 2);
    const float u = t - static_cast<float>(i);
    return ramp[i] + u * (ramp[i + 1] - ramp[i]);
}

void wind_arrows(const WindField& f, WindArrows& out) {
    out.vertices.clear();
    out.arrows = 0;
    const std::uint32_t m[3] = {arrow_count(f.n[0], wind_arrows_across),
                                arrow_count(f.n[1], wind_arrow_layers),
                                arrow_count(f.n[2], wind_arrows_across)};
    struct Sample {
        glm::vec3 at, wind;
    };
    std::vector<Sample> samples;
    samples.reserve(static_cast<std::size_t>(m[0]) * m[1] * m[2]);
    float fastest = 0.0f;
    for (std::uint32_t k = 0; k < m[2]; ++k) {
        for (std::uint32_t j = 0; j < m[1]; ++j) {
            for (std::uint32_t i = 0; i < m[0]; ++i) {
                const glm::vec3 at{arrow_at(f, 0, i, m[0]), arrow_at(f, 1, j, m[1]),
                                   arrow_at(f, 2, k, m[2])};
                const glm::vec3 wind = f.at(at.x, at.y, at.z);
                fastest = std::max(fastest, glm::length(wind));
                samples.push_back({at, wind});
            }
        }
    }
    out.max_speed = fastest;
    if (!(fastest > 0.0f)) {
        return;
    }
    // The fastest arrow spans 0.9 of the smaller horizontal spacing.
    const float spacing = std::min(static_cast<float>(f.n[0]) / (f.inv_cell.x * m[0]),
                                   static_cast<float>(f.n[2]) / (f.inv_cell.z * m[2]));
    const float metres_per_speed = 0.9f * spacing / fastest;
    for (const Sample& s : samples) {
        const float speed = glm::length(s.wind);
        if (!(speed > 0.01f * fastest)) {
            continue;
        }
        const glm::vec3 along = s.wind / speed;
        const glm::vec3 tip = s.at + s.wind * metres_per_speed;
        // The head lies in the plane of the shaft and the vertical (or x
        // for a vertical shaft): seen from above and from the side alike.
        const glm::vec3 across = glm::cross(along, glm::vec3(0.0f, 1.0f, 0.0f));
        const float across_length = glm::length(across);
        const glm::vec3 side =
            across_length > 1e-3f ? across / across_length : glm::vec3(1.0f, 0.0f, 0.0f);
        const float head = 0.3f * speed * metres_per_speed;
        const glm::vec3 color = wind_speed_color(speed / fastest);
        add_segment(out.vertices, s.at, tip, color);
        add_segment(out.vertices, tip, tip - head * along + 0.5f * head * side, color);
        add_segment(out.vertices, tip, tip - head * along - 0.5f * head * side, color);
        ++out.arrows;
    }
}

} // namespace snow
