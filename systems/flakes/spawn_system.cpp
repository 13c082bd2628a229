// spawn: inactive flakes activate [WF §4] on the top and upwind sides
// of the simulation bounds [WF §5] as parcels of real flakes of one size,
// drawn from the emitter's spectrum (snowfall.hpp). Every draw is keyed by
// (seed, tick, flake id, stream).
#include "ecs/rng.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/mass_ledger.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/units.hpp"
#include "systems/flakes/emitter.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/flakes/snowfall.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/wind.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// Inflow through the top and the four sides: area × speed into the box.
struct FaceWeights {
    float w[5]; // top, -x, +x, -z, +z
    float total;
};

FaceWeights face_weights(const Aabb& b, const glm::vec3& wind, float fall_speed) {
    const glm::vec3 s = b.size();
    FaceWeights f{{s.x * s.z * fall_speed, s.y * s.z * std::max(wind.x, 0.0f),
                   s.y * s.z * std::max(-wind.x, 0.0f), s.y * s.x * std::max(wind.z, 0.0f),
                   s.y * s.x * std::max(-wind.z, 0.0f)},
                  0.0f};
    for (const float w : f.w) {
        f.total += w;
    }
    return f;
}

/// The spawn region: the bounds above the lowest bare ground (surfaces lying
/// on nothing), so side-born flakes never start underground.
Aabb spawn_region(const World& w, const Aabb& bounds) {
    float ground = bounds.max.y;
    bool any = false;
    w.each<SnowSurface, SurfaceOf>([&](Entity, const SnowSurface& s, const SurfaceOf& of) {
        if (!of.owner.is_null()) {
            return;
        }
        // The bare top is a plane: its lowest point is at a corner cell.
        const std::size_t last_x = s.nx - 1, last_z = s.nz - 1;
        for (const std::size_t i :
             {s.index(0, 0), s.index(static_cast<std::uint32_t>(last_x), 0),
              s.index(0, static_cast<std::uint32_t>(last_z)),
              s.index(static_cast<std::uint32_t>(last_x), static_cast<std::uint32_t>(last_z))}) {
            ground = std::min(ground, s.height(s.base_level[i]));
            any = true;
        }
    });
    Aabb r = bounds;
    if (any) {
        r.min.y = std::clamp(ground, bounds.min.y, bounds.max.y);
    }
    return r;
}

/// A point on face `face`, given two uniforms; kept a hair inside the box.
glm::vec3 point_on_face(const Aabb& b, int face, float u, float v) {
    const float eps = 1e-3f;
    const glm::vec3 lo = b.min + eps, hi = b.max - eps;
    const float x = lo.x + (hi.x - lo.x) * u, y = lo.y + (hi.y - lo.y) * v;
    const float z_from_u = lo.z + (hi.z - lo.z) * u, z_from_v = lo.z + (hi.z - lo.z) * v;
    switch (face) {
    case 0:
        return {x, hi.y, z_from_v};
    case 1:
        return {lo.x, y, z_from_u};
    case 2:
        return {hi.x, y, z_from_u};
    case 3:
        return {x, y, lo.z};
    default:
        return {x, y, hi.z};
    }
}

} // namespace

void spawn_system(World& w) {
    const auto& cfg = w.resource<SimConfig>();
    const std::uint64_t tick = w.resource<SimClock>().tick;
    auto& pool = w.resource<FlakePool>();
    auto& ledger = w.resource<MassLedger>();
    const auto* wind = w.try_resource<Wind>();
    const glm::vec3 air = wind ? wind->current : glm::vec3(0.0f);
    const float gravity = std::max(-cfg.gravity.y, 1e-6f);

    const Aabb region = spawn_region(w, cfg.bounds);
    const glm::vec3 extent = cfg.bounds.size();
    const double ground_area = static_cast<double>(extent.x) * extent.z;
    std::uint32_t emitter_index = 0;
    w.each<Emitter>([&](Entity, const Emitter& em) {
        const RngKey count_key{cfg.seed, tick, emitter_index++, random_stream::spawn_activate};
        // floor(rate·dt + u): the expected count per tick, exactly on average.
        const double expected = static_cast<double>(em.rate) * cfg.dt;
        auto n = static_cast<std::uint64_t>(expected + rng_uniform(count_key));
        const SpectrumMeans means = spectrum_means(em);
        const FaceWeights faces = face_weights(region, air, static_cast<float>(means.fall_speed));
        const double multiplicity = parcel_multiplicity(em, ground_area, means);
        for (; n > 0; --n) {
            std::uint32_t slot = 0;
            if (!pool.acquire(slot)) {
                return; // pool full: the limit holds without allocating
            }
            // Keyed by the flake's id: the draws do not depend on which slot was free.
            const std::uint32_t id = pool.id[slot];
            const float size =
                size_at(em, rng_uniform({cfg.seed, tick, id, random_stream::spawn_size}));
            // floor(x + u): whole units, the declared snowfall on average.
            const double units_expected = parcel_units(em, multiplicity, size);
            const auto units = static_cast<std::uint32_t>(std::min(
                units_expected + rng_uniform({cfg.seed, tick, id, random_stream::spawn_rounding}),
                double{max_flake_units})); // validate(Emitter, bounds) keeps parcels below
            if (units == 0) {
                pool.release(slot); // this parcel rounded to no snow
                continue;
            }
            const RngKey k{cfg.seed, tick, id, random_stream::spawn_position};
            float pick = rng_uniform(k, 0) * faces.total;
            int face = 0;
            while (face < 4 && pick >= faces.w[face]) {
                pick -= faces.w[face];
                ++face;
            }
            const glm::vec3 p = point_on_face(region, face, rng_uniform(k, 1), rng_uniform(k, 2));
            const float fall = fall_speed(em.crystal, size);
            pool.px[slot] = p.x;
            pool.py[slot] = p.y;
            pool.pz[slot] = p.z;
            // Born at terminal velocity: carried by the air, falling at `fall`.
            pool.vx[slot] = air.x;
            pool.vy[slot] = air.y - fall;
            pool.vz[slot] = air.z;
            // Drag such that m·g = k·fall: the size's terminal speed emerges
            // from F = m·g + k·(w − v) [LH74].
            pool.k_over_m[slot] = gravity / fall;
            pool.size[slot] = size;
            pool.mass_units[slot] = units;
            ledger.spawned += units;
        }
    });
}

} // namespace snow
