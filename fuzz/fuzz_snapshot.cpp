// Fuzz target: snapshot bytes restored into a running simulation, as
// Simulation::load_bytes gets them from a save file or the network
// (fuzz_units.hpp: the stormy yard, every kind of state). Bytes are either
// restored, and the simulation then ticks with its mass balanced, or refused
// with the state unchanged; anything else aborts.
//
// SNOW_FUZZ_WRITE_SEED=FILE: write a valid snapshot of the scene to FILE and
// exit (scripts/fuzz.sh seeds the corpus with it, so the seed always matches
// the current format).
#include "fuzz/fuzz_units.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace {

std::unique_ptr<snow::Simulation> sim;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    sim = snow::fuzz::snapshot_scene();
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
    const std::string problem =
        snow::fuzz::snapshot_unit(*sim, {reinterpret_cast<const std::byte*>(data), size});
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_snapshot: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
