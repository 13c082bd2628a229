#include "systems/flakes/emitter.hpp"

namespace snow {

Invalid validate(const Emitter& m) {
    Invalid e = check_fields("emitter", emitter_fields, m);
    check::ordered(e, "emitter", "mass_min_g", m.mass_min_g, "mass_max_g", m.mass_max_g);
    check::ordered(e, "emitter", "size_min", m.size_min, "size_max", m.size_max);
    check::ordered(e, "emitter", "fall_speed_min", m.fall_speed_min, "fall_speed_max",
                   m.fall_speed_max);
    return e;
}

} // namespace snow
