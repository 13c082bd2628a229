// occlusion: the sky camera of [SKY]. An orthographic depth map from above
// over the bounds' XZ extent, rasterised on the CPU: per texel the highest
// geometry and its entity. With a tilt the rays lean downwind, like the flakes,
// so lee sides get less exposure ([SKY Limitations 2]: wind). Refreshed
// only when the sources (source_versions.hpp) or the quantised wind direction
// changed; occlusion_raster.cpp draws it.
#include "systems/sky/occlusion.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/state_bytes.hpp"
#include "systems/geometry/occlusion_raster.hpp"
#include "systems/snowpack/snow_cover.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/wind.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace snow {

namespace {

/// Where and how the map is laid out; a change from the stored one means a refresh.
struct Layout {
    float x0 = 0.0f, z0 = 0.0f, texel = 1.0f;
    std::uint32_t width = 1, height = 1;
    float wind_angle = occlusion_no_lean;
    float shear_x = 0.0f, shear_z = 0.0f;
};

/// Wind direction quantised to occlusion_wind_steps, with hysteresis: the
/// stored direction is kept while the wind stays within 3/4 of a step of it,
/// so a wind wobbling on a step boundary does not refresh every tick.
float quantised_angle(double angle, float previous) {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    const double step = two_pi / occlusion_wind_steps;
    if (previous != occlusion_no_lean) {
        double d = std::fabs(angle - previous);
        d = std::min(d, two_pi - d);
        if (d <= 0.75 * step) {
            return previous;
        }
    }
    const auto k =
        static_cast<std::uint32_t>(std::floor(angle / step + 0.5)) % occlusion_wind_steps;
    return static_cast<float>(k * step);
}

Layout layout_for(const World& w, const OcclusionCamera& cam, const OcclusionMap& previous) {
    Layout l;
    const Aabb& b = w.resource<SimConfig>().bounds;
    l.x0 = b.min.x;
    l.z0 = b.min.z;
    const OcclusionGrid grid = occlusion_grid(w, cam);
    l.texel = grid.texel;
    l.width = grid.width;
    l.height = grid.height;
    const auto* wind = w.try_resource<Wind>();
    if (cam.tilt == 0.0f || wind == nullptr) {
        return l;
    }
    const double wx = wind->current.x, wz = wind->current.z;
    if (!(wx * wx + wz * wz > 1e-12)) {
        return l; // calm (or non-finite): no direction to lean along
    }
    double angle = std::atan2(wz, wx);
    angle = angle < 0.0 ? angle + 2.0 * std::numbers::pi : angle;
    // A map never built has no direction to hold on to.
    l.wind_angle = quantised_angle(angle, previous.built ? previous.wind_angle : occlusion_no_lean);
    const double t = std::tan(static_cast<double>(cam.tilt));
    l.shear_x = static_cast<float>(t * std::cos(static_cast<double>(l.wind_angle)));
    l.shear_z = static_cast<float>(t * std::sin(static_cast<double>(l.wind_angle)));
    return l;
}

bool up_to_date(const OcclusionMap& m, const Layout& l, const SourceVersions& sources) {
    return m.built && m.built_from == sources && m.wind_angle == l.wind_angle &&
           m.shear_x == l.shear_x && m.shear_z == l.shear_z && m.x0 == l.x0 && m.z0 == l.z0 &&
           m.texel == l.texel && m.width == l.width && m.height == l.height;
}

} // namespace

OcclusionGrid occlusion_grid(const World& w, const OcclusionCamera& cam) {
    OcclusionGrid g;
    const glm::vec3 ext = w.resource<SimConfig>().bounds.size();
    const std::uint32_t res = std::max<std::uint32_t>(cam.resolution, 1);
    const float longest = std::max(ext.x, ext.z);
    g.texel = longest > 0.0f ? longest / static_cast<float>(res) : 1.0f;
    g.width =
        std::clamp<std::uint32_t>(static_cast<std::uint32_t>(std::ceil(ext.x / g.texel)), 1, res);
    g.height =
        std::clamp<std::uint32_t>(static_cast<std::uint32_t>(std::ceil(ext.z / g.texel)), 1, res);
    return g;
}

void prepare_occlusion(World& w) {
    const auto* cam = w.try_resource<OcclusionCamera>();
    if (cam == nullptr) {
        return;
    }
    auto* map = w.try_resource<OcclusionMap>();
    if (map == nullptr) {
        map = &w.set_resource<OcclusionMap>(); // not built: as if absent (hash, snapshots)
    }
    const OcclusionGrid grid = occlusion_grid(w, *cam);
    const std::size_t texels = static_cast<std::size_t>(grid.width) * grid.height;
    map->top_y.reserve(texels);
    map->top_id.reserve(texels);
}

float occlusion_exposure(const OcclusionMap& map, float x, float y, float z, float tolerance) {
    std::uint32_t i = 0, j = 0;
    if (!occlusion_texel(map, x, y, z, i, j)) {
        return 1.0f; // nothing known above a point outside the map
    }
    return y >= map.top_y[static_cast<std::size_t>(j) * map.width + i] - tolerance ? 1.0f : 0.0f;
}

void surface_exposure(const OcclusionMap& map, const SnowSurface& s, Vector<float>& out,
                      float tolerance) {
    out.resize(s.cell_count());
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const std::size_t i = s.index(ix, iz);
            const float x = s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell;
            const float z = s.z0 + (static_cast<float>(iz) + 0.5f) * s.cell;
            out[i] = occlusion_exposure(map, x, s.top_y(i), z, tolerance);
        }
    }
}

void occlusion_system(World& w) {
    const auto* cam = w.try_resource<OcclusionCamera>();
    if (cam == nullptr) {
        return;
    }
    prepare_occlusion(w);
    auto* map = &w.resource<OcclusionMap>();
    const SourceVersions sources = source_versions(w);
    const Layout l = layout_for(w, *cam, *map);
    if (up_to_date(*map, l, sources)) {
        return;
    }
    map->x0 = l.x0;
    map->z0 = l.z0;
    map->texel = l.texel;
    map->width = l.width;
    map->height = l.height;
    map->wind_angle = l.wind_angle;
    map->shear_x = l.shear_x;
    map->shear_z = l.shear_z;
    rasterise_geometry(w, *map, is_cover);
    map->built = true;
    map->built_from = sources;
    ++map->version;
    if (auto* counters = w.try_resource<SimCounters>()) {
        ++counters->occlusion_refreshes;
    }
}

namespace {

template <typename Io, typename Map>
void map_record(Io& io, Map& m) {
    for (auto* v : {&m.x0, &m.z0, &m.texel, &m.wind_angle, &m.shear_x, &m.shear_z}) {
        io(*v);
    }
    io(m.width);
    io(m.height);
    io(m.top_y);
    io(m.top_id);
    io(m.built);
    for (auto* v : {&m.built_from.solids, &m.built_from.surfaces, &m.built_from.occlusion}) {
        io(*v);
    }
}

} // namespace

void save_state(ByteWriter& out, const OcclusionMap& m) {
    map_record(out, m);
}

void load_state(ByteReader& in, OcclusionMap& m) {
    map_record(in, m);
    const std::size_t texels = static_cast<std::size_t>(m.width) * m.height;
    in.require(m.top_y.size() == texels && m.top_id.size() == texels,
               "has texels of another size than its width and height");
    bool ok = std::isfinite(m.texel) && m.texel > 0.0f;
    for (const float v : {m.x0, m.z0, m.wind_angle, m.shear_x, m.shear_z}) {
        ok = ok && std::isfinite(v);
    }
    in.require(ok, "has a non-finite or empty projection");
}

Invalid validate(const OcclusionCamera& cam) {
    return check_fields("occlusion", occlusion_fields, cam);
}

void hash_state(StateHasher& h, const OcclusionMap& m, bool stale) {
    ByteWriter out(h);
    for (const float v : {m.x0, m.z0, m.texel}) {
        out(v);
    }
    out(m.width);
    out(m.height);
    for (const float v : {m.wind_angle, m.shear_x, m.shear_z}) {
        out(v);
    }
    out(stale);
    if (stale) {
        out(m.top_y);
        out(m.top_id);
    }
}

} // namespace snow
