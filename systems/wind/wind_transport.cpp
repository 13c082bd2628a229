#include "systems/wind/wind_transport.hpp"

namespace snow {

Invalid validate(const WindTransportDef& t) {
    Invalid bad = check_fields("wind.field.transport", wind_transport_fields, t);
    if (bad.empty() && !(t.height > t.roughness)) {
        // The log law's ln(z/z0) must be positive.
        bad = {"wind.field.transport.height", "must be above roughness (got " +
                                                  number_text(t.height) +
                                                  " <= " + number_text(t.roughness) + ")"};
    }
    return bad;
}

} // namespace snow
