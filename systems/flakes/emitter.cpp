#include "systems/flakes/emitter.hpp"

#include "ecs/state_hash.hpp"

namespace snow {

Invalid validate(const Emitter& m) {
    Invalid e = check_fields("emitter", emitter_fields, m);
    check::ordered(e, "emitter", "mass_min_g", m.mass_min_g, "mass_max_g", m.mass_max_g);
    check::ordered(e, "emitter", "size_min", m.size_min, "size_max", m.size_max);
    check::ordered(e, "emitter", "fall_speed_min", m.fall_speed_min, "fall_speed_max",
                   m.fall_speed_max);
    return e;
}

void hash_state(StateHasher& h, const Emitter& m) {
    for (const float v : {m.rate, m.mass_min_g, m.mass_max_g, m.size_min, m.size_max,
                          m.fall_speed_min, m.fall_speed_max}) {
        h.value(v);
    }
}

} // namespace snow
