// snow_export_sample FILE.glb: writes the .glb of the cover test scene
// (tests/support/cover_scene.hpp) for the glTF validator test, since scene
// files cannot declare covers yet.
#include "game/export/snow_export.hpp"
#include "tests/support/cover_scene.hpp"

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: snow_export_sample FILE.glb\n");
        return 2;
    }
    try {
        const snow::test::CoverScene scene = snow::test::snowed_cover_scene(600);
        snow::export_snow_glb(*scene.sim, argv[1]);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "snow_export_sample: %s\n", e.what());
        return 1;
    }
}
