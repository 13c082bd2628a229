#include "systems/flakes/emitter.hpp"

#include "ecs/error.hpp"
#include "ecs/state_hash.hpp"
#include "systems/core/units.hpp"
#include "systems/flakes/snowfall.hpp"

#include <cmath>
#include <string>

namespace snow {

Invalid validate(const Emitter& m) {
    Invalid e = check_fields("emitter", emitter_fields, m);
    check::ordered(e, "emitter", "size_min", m.size_min, "size_max", m.size_max);
    if (e.empty() && m.crystal != CrystalType::dendrite_aggregate &&
        m.crystal != CrystalType::rimed_aggregate) {
        check::fail(e, "emitter.crystal", "a CrystalType", static_cast<double>(m.crystal));
    }
    return e;
}

namespace {

/// A whole parcel rate as the error prints it: every digit while the
/// integer holds it, else 6 significant ones.
std::string parcels_text(double rate) {
    return rate < 1.0e15 ? std::to_string(static_cast<long long>(rate)) : number_text(rate);
}

} // namespace

Invalid validate(const Emitter& m, const Aabb& bounds) {
    Invalid e = validate(m);
    if (!e.empty()) {
        return e;
    }
    const glm::vec3 size = bounds.size();
    const double needed = min_parcel_rate(m, static_cast<double>(size.x) * size.z);
    // A parcel of exactly max_flake_units is fine (spawn never rounds past
    // it): the tolerance only absorbs the last bit of the quotient.
    if (m.rate > 0.0f && m.rate < needed * (1.0 - 1e-9)) {
        check::fail(e, "emitter.rate",
                    ">= " + parcels_text(std::ceil(needed)) +
                        " parcels/s for this snowfall over the bounds (each parcel holds at most " +
                        std::to_string(max_flake_units) + " mass units)",
                    m.rate);
    }
    return e;
}

void hash_state(StateHasher& h, const Emitter& m) {
    for (const float v : {m.rate, m.snowfall_kg_m2_h, m.size_mean, m.size_min, m.size_max}) {
        h.value(v);
    }
    h.value(static_cast<std::uint8_t>(m.crystal));
}

} // namespace snow
