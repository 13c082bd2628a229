#include "game/play/game_options.hpp"

namespace snow {

void apply_timelapse(GameOptions& o) {
    o.headless = true;
    o.frames = 120;
    o.width = 640;
    o.height = 360;
    o.quality = 0;     // low: 30 ticks a second, coarse cells
    o.time_scale = 64; // 64 × 1/30 s: 2.1 simulated seconds a frame, 4.3 minutes in all
    // Weather fast-forwarded: 200 kg/m²/h, 13 times the village's storm, so
    // that 4 minutes lay what a long storm does.
    o.snowfall = 200.0f;
    o.overrides.max_flakes = 400000;
    // The storm blows from the south, towards the buildings' camera-facing
    // sides: drifts grow at the garage's windward face, in view; the house's
    // east roof slides off its eave onto the porch, which no building shelters.
    o.overrides.wind = glm::vec3{0.0f, 0.0f, -2.5f};
    o.camera = CameraMode::fly;
    o.look_from = glm::vec3{0.0f, 4.5f, 8.5f};
    o.look_at = glm::vec3{1.8f, 1.0f, -1.0f};
    o.walk_once_at = 55; // the walker cuts its trail through 3 cm of snow
    o.contact_sheet = 8;
    o.video = true;
    o.bare_meshes = true; // white is only the simulated snow ...
    // ... from 8 mm on: the porch's and roofs' thinner snow shows, the trail
    // reads dark until it refills.
    o.min_snow_depth = 0.008f;
    o.out_dir = "out/timelapse";
}

} // namespace snow
