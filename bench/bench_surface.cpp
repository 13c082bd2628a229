// Surface systems (issue #8): redistribution must cost by the area snow lands
// on (the dirty area), not by the surface's size; spill by the border.
#include "bench_scene.hpp"

#include "systems/api/simulation_internals.hpp"

#include <algorithm>
#include <vector>

namespace snow::bench {
namespace {

/// One square surface of `side` cells of 5 cm, alone in a simulation.
struct Field {
    Simulation sim;
    SurfaceId entity;
    Vector<std::uint32_t> bare; ///< the starting snow (restored between iterations)

    explicit Field(std::uint32_t side, bool spills = false) : sim(SimConfig{}) {
        SurfaceDef d;
        d.cell = 0.05f;
        d.size_x = d.size_z = d.cell * static_cast<float>(side);
        d.spills = spills;
        entity = sim.add_surface(d);
        bare = surface().snow;
    }
    SnowSurface& surface() {
        return InternalAccess::world(sim).get<SnowSurface>(entity_of(entity));
    }
    void land(std::uint32_t ix, std::uint32_t iz, std::uint32_t units) {
        SnowSurface& s = surface();
        s.snow[s.index(ix, iz)] += units;
        s.mark_dirty(ix, iz);
    }
    /// Puts back the starting snow in the cells of [x0, x1] × [z0, z1] (clipped).
    void restore(std::int64_t x0, std::int64_t z0, std::int64_t x1, std::int64_t z1) {
        SnowSurface& s = surface();
        const auto cx0 = static_cast<std::uint32_t>(std::max<std::int64_t>(x0, 0));
        const auto cz0 = static_cast<std::uint32_t>(std::max<std::int64_t>(z0, 0));
        const auto cx1 = static_cast<std::uint32_t>(std::min<std::int64_t>(x1, s.nx - 1));
        const auto cz1 = static_cast<std::uint32_t>(std::min<std::int64_t>(z1, s.nz - 1));
        for (std::uint32_t iz = cz0; iz <= cz1; ++iz) {
            std::copy_n(bare.begin() + static_cast<std::ptrdiff_t>(s.index(cx0, iz)), cx1 - cx0 + 1,
                        s.snow.begin() + static_cast<std::ptrdiff_t>(s.index(cx0, iz)));
        }
        s.clear_dirty();
    }
};

/// Units landing on cell (i, j) of a patch: a rough, fixed pattern of 4 to
/// 14 cm of snow, over the Laplacian cap (2500 units, 5 cm, on 5 cm cells)
/// wherever it meets bare ground, so the smoothing has real work.
std::uint32_t pattern(std::uint32_t i, std::uint32_t j) {
    return 2000 + 500 * ((7 * i + 13 * j) % 11);
}

/// A patch × patch landing pattern at the centre of a side × side surface,
/// then one redistribution tick. The cells a tick can change lie within
/// 64 steps (its iteration cap) of the patch; they are restored untimed.
void redistribute_patch(benchmark::State& state) {
    const auto side = static_cast<std::uint32_t>(state.range(0));
    const auto patch = static_cast<std::uint32_t>(state.range(1));
    Field f(side);
    const std::uint32_t p0 = (side - patch) / 2;
    const std::int64_t reach = 66;
    for (auto _ : state) {
        for (std::uint32_t j = 0; j < patch; ++j) {
            for (std::uint32_t i = 0; i < patch; ++i) {
                f.land(p0 + i, p0 + j, pattern(i, j));
            }
        }
        redistribute_system(InternalAccess::world(f.sim));
        state.PauseTiming();
        f.restore(p0 - reach, p0 - reach, p0 + patch + reach, p0 + patch + reach);
        state.ResumeTiming();
    }
    state.counters["dirty_cells"] = static_cast<double>(patch) * patch;
    state.counters["smoothing_iterations"] =
        static_cast<double>(f.sim.counters().smoothing_iterations) /
        static_cast<double>(state.iterations());
}

/// `landings` single flakes (1 to 40 units, under the cap) scattered over the
/// whole surface (a fixed sequence): the marked rectangle is the whole
/// surface, so this is the cost of the first step's scan of it, which grows
/// with the rectangle's area (SnowSurface keeps one rectangle).
void redistribute_scattered(benchmark::State& state) {
    const auto side = static_cast<std::uint32_t>(state.range(0));
    const auto landings = static_cast<std::uint32_t>(state.range(1));
    Field f(side);
    for (auto _ : state) {
        for (std::uint32_t k = 0; k < landings; ++k) {
            const std::uint32_t h = (k + 1) * 2654435761u;
            f.land((h >> 8) % side, (h >> 20) * 7 % side, 1 + k % 40);
        }
        redistribute_system(InternalAccess::world(f.sim));
        state.PauseTiming();
        f.restore(0, 0, side - 1, side - 1);
        state.ResumeTiming();
    }
    state.counters["landings"] = landings;
}

/// A roof of side × side cells whose every border cell holds 2500 units over
/// its edge limit: one spill tick sheds them all as flakes (3 per cell).
void spill_border(benchmark::State& state) {
    const auto side = static_cast<std::uint32_t>(state.range(0));
    Field f(side, true);
    SnowSurface& s = f.surface();
    for (std::uint32_t iz = 0; iz < side; ++iz) {
        for (std::uint32_t ix = 0; ix < side; ++ix) {
            const bool border = ix == 0 || iz == 0 || ix + 1 == side || iz + 1 == side;
            f.bare[s.index(ix, iz)] = border ? s.edge_limit_units + 2500 : 0;
        }
    }
    InternalAccess::world(f.sim).resource<MassLedger>().spawned = s.settled_units();
    f.restore(0, 0, side - 1, side - 1);
    const auto start = save_snapshot(f.sim);
    for (auto _ : state) {
        spill_system(InternalAccess::world(f.sim));
        state.PauseTiming();
        restore_snapshot(f.sim, *start);
        state.ResumeTiming();
    }
    state.counters["border_cells"] = 4.0 * (side - 1);
}

} // namespace

BENCHMARK(redistribute_patch)
    ->Name("BM_Redistribute")
    ->ArgNames({"side", "patch"})
    ->ArgsProduct({{256, 1024}, {8, 32, 128}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(redistribute_scattered)
    ->Name("BM_RedistributeScattered")
    ->ArgNames({"side", "landings"})
    ->ArgsProduct({{256, 1024}, {256}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(spill_border)
    ->Name("BM_Spill")
    ->ArgNames({"side"})
    ->Arg(32)
    ->Arg(256)
    ->Unit(benchmark::kMicrosecond);

} // namespace snow::bench
