#include "systems/api/spectral_snow.hpp"

#include <bit>
#include <string>
#include <utility>

namespace snow {

Invalid validate(const SpectralSnow& s) {
    Invalid e = check_fields("spectral", spectral_fields, s);
    for (const auto& [field, size] :
         {std::pair{"spectral.size_xy", s.size_xy}, std::pair{"spectral.size_t", s.size_t}}) {
        if (!std::has_single_bit(size)) {
            check::fail(e, field, "a power of two", size);
        }
    }
    check::ordered(e, "spectral", "band_low", s.band_low, "band_high", s.band_high);
    // The band must fit the volume: at most its Nyquist frequency [LZ].
    check::number(e, "spectral.band_high", up_to(s.size_xy / 2.0), s.band_high);
    return e;
}

} // namespace snow
