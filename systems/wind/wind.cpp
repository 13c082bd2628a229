#include "systems/wind/wind.hpp"

#include "systems/core/state_bytes.hpp"

namespace snow {

namespace {

template <typename Io, typename W>
void wind_record(Io& io, W& w) {
    for (auto* v : {&w.base, &w.current, &w.deviation}) {
        io(*v);
    }
    for (auto* v : {&w.walk, &w.max_deviation, &w.gust_strength, &w.gust_rate, &w.gust_duration,
                    &w.gust_left}) {
        io(*v);
    }
}

} // namespace

void save_state(ByteWriter& out, const Wind& w) {
    wind_record(out, w);
}

void load_state(ByteReader& in, Wind& w) {
    wind_record(in, w);
}

Invalid validate(const Wind& w) {
    return check_fields("wind", wind_fields, w);
}

} // namespace snow
