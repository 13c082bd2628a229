// Fuzz target: a scene from memory (.gltf text when SNOW_FUZZ_GLB is 0, .glb
// bytes when 1), as load_scene_memory gets it from a host with a small work
// budget (fuzz_units.hpp). A scene either loads, and then ticks twice with
// its mass balanced and every value finite, or is refused with one error;
// anything else aborts.
#include "fuzz/fuzz_units.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    if (glb != (SNOW_FUZZ_GLB != 0)) {
        return -1; // the other target's input: not added to this corpus
    }
    const std::string problem = snow::fuzz::scene_unit({reinterpret_cast<const char*>(data), size});
    if (!problem.empty()) {
        std::fprintf(stderr, "fuzz_scene: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
