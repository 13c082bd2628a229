// A host that loads a glTF scene with snow::scene, lets it snow for two
// seconds and renders one headless frame with snow::render to a PNG. Only
// <snow/scene.hpp> and <snow/render.hpp>.
//   embed_scene [scene.gltf] [out.png]
#include <snow/render.hpp>
#include <snow/scene.hpp>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    const std::string scene_path = argc > 1 ? argv[1] : SNOW_EXAMPLE_SCENE;
    const std::string out_path = argc > 2 ? argv[2] : "embed_scene.png";
    snow::SceneLoadResult scene = snow::load_scene_file(scene_path);
    if (!scene.sim) {
        std::fprintf(stderr, "embed_scene: %s\n", scene.error.c_str());
        return 2;
    }
    try {
        scene.sim->run(120);
        snow::ContextRequest request;
        request.backend = snow::ContextBackend::headless;
        request.width = 320;
        request.height = 240;
        auto context = snow::make_context(request);
        snow::Renderer renderer(*context);
        renderer.render(*scene.sim, scene.visuals,
                        snow::ViewCamera::from_def(scene.visuals.camera));
        snow::write_png(out_path, renderer.read_pixels());
        const snow::MassReport m = scene.sim->mass();
        std::printf("embed_scene: %s, %zu meshes, %u flakes drawn, settled %llu units, wrote %s\n",
                    scene.name.c_str(), scene.visuals.meshes.size(),
                    renderer.timings().flakes_drawn, static_cast<unsigned long long>(m.settled),
                    out_path.c_str());
        return m.balanced() && renderer.timings().flakes_drawn > 0 ? 0 : 1;
    } catch (const snow::Error& e) {
        std::fprintf(stderr, "embed_scene: %s\n", e.what());
        return 1;
    }
}
