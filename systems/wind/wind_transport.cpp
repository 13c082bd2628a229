#include "systems/wind/wind_transport.hpp"

namespace snow {

Invalid validate(const WindTransportDef& t) {
    return check_fields("wind.field.transport", wind_transport_fields, t);
}

} // namespace snow
