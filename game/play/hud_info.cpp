#include "game/play/hud_info.hpp"
#include "systems/api/simulation_internals.hpp"

#include "game/play/quality.hpp"

namespace snow {

HudInfo hud_info(const GameSession& session, float fps) {
    const Simulation& sim = session.sim();
    const CameraController& camera = session.camera();
    HudInfo info;
    info.fps = fps;
    info.paused = session.paused();
    info.help = session.help();
    info.fog_on = session.visuals().fog.has_value();
    info.quality = quality_presets[session.quality()].name;
    info.camera_mode = camera_mode_name(camera.mode());
    info.last_message = session.message();
    info.time_scale = session.time_scale().factor();
    info.ticks_per_frame = session.ticks_last_frame();
    info.ticks_capped = session.ticks_capped();
    const Walker* walker = session.walker();
    if (camera.mode() == CameraMode::walk && walker) {
        info.depth_under = walker->depth_under(sim);
        info.depth_ahead = walker->depth_ahead(sim, camera.facing());
    }
    return info;
}

} // namespace snow
