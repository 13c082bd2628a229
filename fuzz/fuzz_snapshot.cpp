// Fuzz target: snapshot bytes restored into a running simulation, as
// Simulation::load_bytes gets them from a save file or the network. The scene
// is the stormy yard (every kind of state: flakes, surfaces, a cover, bodies,
// a wind field, transport, the sky map) with few flakes, so a snapshot stays
// small. Bytes are either restored, and the simulation then ticks with its
// mass balanced, or refused with the state unchanged; anything else aborts.
//
// SNOW_FUZZ_WRITE_SEED=FILE: write a valid snapshot of the scene to FILE and
// exit (scripts/fuzz.sh seeds the corpus with it, so the seed always matches
// the current format).
#include "tests/scenes/sample_scenes.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <span>

namespace {

std::unique_ptr<snow::Simulation> sim;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    sim = snow::make_stormy_yard(1, nullptr, 64);
    for (int t = 0; t < 5; ++t) {
        sim->tick();
    }
    if (const char* seed = std::getenv("SNOW_FUZZ_WRITE_SEED")) {
        const std::vector<std::byte> bytes = sim->save_bytes();
        std::FILE* f = std::fopen(seed, "wb");
        const bool ok = f && std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
        if (!f || std::fclose(f) != 0 || !ok) {
            std::fprintf(stderr, "fuzz_snapshot: cannot write %s\n", seed);
            std::exit(2);
        }
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::uint64_t before = sim->state_hash();
    try {
        sim->load_bytes(std::span(reinterpret_cast<const std::byte*>(data), size));
    } catch (const snow::SimulationError&) {
        if (sim->state_hash() != before) {
            std::abort(); // a refused snapshot changed the state
        }
        return 0;
    }
    sim->tick();
    if (!sim->mass().balanced() || sim->nonfinite_count() != 0) {
        std::abort();
    }
    return 0;
}
