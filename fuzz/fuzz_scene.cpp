// Fuzz target: a scene from memory (.gltf text when SNOW_FUZZ_GLB is 0, .glb
// bytes when 1), as load_scene_memory gets it from a host. A scene either
// loads, and then ticks twice with its mass balanced and every value finite,
// or is refused with one error; anything else aborts.
#include <snow/scene.hpp>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    if (glb != (SNOW_FUZZ_GLB != 0)) {
        return -1; // the other target's input: not added to this corpus
    }
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    snow::SceneLoadResult scene = snow::load_scene_memory(bytes, "fuzz");
    if (!scene.sim) {
        if (scene.error.empty()) {
            std::abort(); // refused without saying why
        }
        return 0;
    }
    scene.sim->tick();
    scene.sim->tick();
    if (!scene.sim->mass().balanced() || scene.sim->nonfinite_count() != 0) {
        std::abort();
    }
    return 0;
}
