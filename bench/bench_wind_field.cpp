// Wind field costs (issue #15): one solver step at N × N/4 × N cells over
// the benchmark yard (garage and snowman as obstacles); the integrate pass
// with flakes dragging towards the field's wind they hold, sampled every
// sample_every ticks (compare ns_per_flake with BM_Integrate: the difference
// is the sampling); and the wind transport over a snow surface of which only
// a windy square is above the threshold (the cost must follow that square,
// not the surface).
#include "bench_scene.hpp"

#include "systems/api/simulation_internals.hpp"
#include "systems/core/mass_ledger.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <cmath>
#include <vector>

namespace snow::bench {
namespace {

WindFieldDef field_of_side(std::uint32_t side) {
    WindFieldDef d;
    d.cells_x = d.cells_z = side;
    d.cells_y = side / 4;
    d.update_every = 1; // every call of the system is a step
    return d;
}

void field_step(benchmark::State& state) {
    YardOptions o;
    o.emitter_rate = 0.0f;
    auto sim = make_yard(o);
    sim->set_wind_field(field_of_side(static_cast<std::uint32_t>(state.range(0))));
    sim->run(60); // initialised and developing
    for (auto _ : state) {
        wind_field_system(InternalAccess::world(*sim));
    }
    const auto cells = static_cast<double>(state.range(0) * state.range(0) * (state.range(0) / 4));
    state.counters["cells"] = cells;
    state.counters["ns_per_cell"] =
        benchmark::Counter(cells * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void integrate_in_field(benchmark::State& state) {
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)),
                  static_cast<unsigned>(state.range(1)));
    WindFieldDef def = field_of_side(64);
    def.sample_every = static_cast<std::uint32_t>(state.range(2));
    bw.sim->set_wind_field(def);
    World& w = InternalAccess::world(*bw.sim);
    flake_order_system(w); // in spatial order, as a running simulation keeps them
    wind_field_system(w);  // the first step fills the field
    integrate_system(w);   // and every flake takes its first sample
    bw.start = save_snapshot(*bw.sim);
    for (auto _ : state) {
        bw.step(state, [&] { integrate_system(w); });
    }
    bw.clock.report(state);
}

/// A side × side surface of 10 cm cells under 5 cm of snow on the ground,
/// and a field whose air is still but for a windy × windy square at the
/// surface's centre, blowing 10 m/s along +x (twice the threshold).
struct WindySquare {
    Simulation sim;
    SurfaceId surface;
    Vector<std::uint32_t> snow; ///< the starting snow

    WindySquare(std::uint32_t side, std::uint32_t windy) : sim(config(side)) {
        SurfaceDef d;
        d.cell = 0.1f;
        d.size_x = d.size_z = d.cell * static_cast<float>(side);
        d.spills = false; // nothing leaves as clumps: the plan and the moves alone
        surface = sim.add_surface(d);
        WindFieldDef field;
        field.cells_x = field.cells_z = side / 4; // 40 cm cells
        field.cells_y = 4;
        field.update_every = 1; // every call of the transport is a field step's
        sim.set_wind_field(field);
        sim.set_wind_transport(WindTransportDef{});
        World& w = InternalAccess::world(sim);
        SnowSurface& s = w.get<SnowSurface>(entity_of(surface));
        const auto units = static_cast<std::uint32_t>(std::lround(0.05f / s.unit_height));
        std::fill(s.snow.begin(), s.snow.end(), units);
        w.resource<MassLedger>().spawned += units * static_cast<std::uint64_t>(s.snow.size());
        snow = s.snow;
        blow_in_square(w.resource<WindField>(), d.size_x, 0.1f * static_cast<float>(windy));
    }

    static SimConfig config(std::uint32_t side) {
        SimConfig c;
        c.bounds = {{0.0f, 0.0f, 0.0f},
                    {0.1f * static_cast<float>(side), 2.0f, 0.1f * static_cast<float>(side)}};
        return c;
    }

    /// The field as if stepped: wind in the square [c − h, c + h]² (c the
    /// centre of an `extent` square, h half of `width`), still air elsewhere.
    static void blow_in_square(WindField& f, float extent, float width) {
        const Lattice& c = f.centre;
        const float lo = 0.5f * (extent - width), hi = 0.5f * (extent + width);
        for (std::int32_t k = 0; k < c.dim[2]; ++k) {
            for (std::int32_t j = 0; j < c.dim[1]; ++j) {
                for (std::int32_t i = 0; i < c.dim[0]; ++i) {
                    const float x = f.origin.x + (static_cast<float>(i) - 0.5f) / f.inv_cell.x;
                    const float z = f.origin.z + (static_cast<float>(k) - 0.5f) / f.inv_cell.z;
                    const bool inside = x > lo && x < hi && z > lo && z < hi;
                    f.at_centre[0][static_cast<std::size_t>(c.index(i, j, k))] =
                        inside ? 10.0f : 0.0f;
                }
            }
        }
        pack_centre(f);
        f.steps = 1;
        f.wait = 0;
    }

    void restore() {
        SnowSurface& s = InternalAccess::world(sim).get<SnowSurface>(entity_of(surface));
        s.snow = snow;
        s.clear_dirty();
    }
};

void transport(benchmark::State& state) {
    const auto side = static_cast<std::uint32_t>(state.range(0));
    const auto windy = static_cast<std::uint32_t>(state.range(1));
    WindySquare ws(side, windy);
    World& w = InternalAccess::world(ws.sim);
    std::uint64_t calls = 0;
    for (auto _ : state) {
        wind_transport_system(w);
        if (++calls % restore_every == 0) {
            state.PauseTiming();
            ws.restore();
            state.ResumeTiming();
        }
    }
    const double active = static_cast<double>(windy) * windy;
    state.counters["windy_cells"] = active;
    state.counters["ns_per_windy_cell"] =
        benchmark::Counter(active * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK(field_step)
    ->Name("BM_WindFieldStep")
    ->ArgName("cells")
    ->Arg(32)
    ->Arg(64)
    ->Arg(128)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(integrate_in_field)
    ->Name("BM_IntegrateInField")
    ->ArgNames({"flakes", "threads", "sample_every"})
    ->ArgsProduct({{10000, 100000, 1000000}, {1, 2}, {1, 16, 32}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(transport)
    ->Name("BM_WindTransport")
    ->ArgNames({"side", "windy"})
    ->Args({256, 16})
    ->Args({256, 64})
    ->Args({256, 256})
    ->Args({1024, 16})
    ->Args({1024, 64})
    ->Args({1024, 256})
    ->Unit(benchmark::kMicrosecond);

} // namespace snow::bench
