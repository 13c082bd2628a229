// wind_field: steps the declared field every update_every ticks, after the
// global wind moved (its walk and gusts are the inflow) and before flakes
// integrate in it. Obstacles are re-marked when the solids or the surfaces
// changed, or the snow moved the ground.
#include "systems/api/systems.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/source_versions.hpp"
#include "systems/wind/wind.hpp"
#include "systems/wind/wind_field_solver.hpp"

namespace snow {

void prepare_wind_field(World& w) {
    const auto* f = w.try_resource<WindField>();
    if (f == nullptr) {
        return;
    }
    auto* s = w.try_resource<WindFieldSolver>();
    if (s == nullptr) {
        s = &w.set_resource<WindFieldSolver>(); // not built: the tick marks the obstacles
    }
    reserve_solver(*f, *s);
}

void wind_field_system(World& w) {
    prepare_wind_field(w);
    WindField& f = w.resource<WindField>();
    auto* s = &w.resource<WindFieldSolver>();
    const SourceVersions v = source_versions(w);
    // The ground follows the snow (its drifts shape the air): looked at only
    // before a step.
    if (!s->built || s->built_from_solids != v.solids || s->built_from_surfaces != v.surfaces ||
        (f.wait == 0 && ground_moved(w, f, *s))) {
        mark_obstacles(w, f, *s);
        apply_obstacles(f, *s);
        s->built = true;
        s->built_from_solids = v.solids;
        s->built_from_surfaces = v.surfaces;
    }
    if (f.wait > 0) {
        --f.wait;
        return;
    }
    f.wait = f.def.update_every - 1;
    const auto* wind = w.try_resource<Wind>();
    const float dt = w.resource<SimConfig>().dt * static_cast<float>(f.def.update_every);
    step_wind_field(f, *s, wind != nullptr ? wind->current : glm::vec3(0.0f), dt);
}

} // namespace snow
