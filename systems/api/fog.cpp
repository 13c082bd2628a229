#include "systems/api/fog.hpp"

#include <string>

namespace snow {

Invalid validate(const Fog& f) {
    Invalid e = check_fields("fog", fog_fields, f);
    check::ordered(e, "fog", "layer_bottom", f.layer_bottom, "layer_top", f.layer_top);
    for (std::size_t i = 0; i < f.puffs.size() && e.empty(); ++i) {
        check_fields(e, "fog.puffs[" + std::to_string(i) + "]", fog_puff_fields, f.puffs[i]);
    }
    return e;
}

} // namespace snow
