// Wind field costs (issue #15): one solver step at N × N/4 × N cells over
// the benchmark yard (garage and snowman as obstacles), and the integrate
// pass with flakes reading the field instead of the global wind (compare
// ns_per_flake with BM_Integrate: the difference is the sampling).
#include "bench_scene.hpp"

#include "systems/internal_access.hpp"

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
    bw.sim->set_wind_field(field_of_side(64));
    wind_field_system(InternalAccess::world(*bw.sim)); // the first step fills the field
    bw.start = bw.sim->save();
    for (auto _ : state) {
        bw.step(state, [&] { integrate_system(InternalAccess::world(*bw.sim)); });
    }
    bw.clock.report(state);
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
    ->ArgNames({"flakes", "threads"})
    ->ArgsProduct({{10000, 100000, 1000000}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace snow::bench
