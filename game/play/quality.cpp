#include "game/play/quality.hpp"

namespace snow {

std::optional<std::size_t> find_quality(std::string_view name) {
    for (std::size_t i = 0; i < quality_presets.size(); ++i) {
        if (quality_presets[i].name == name) {
            return i;
        }
    }
    return std::nullopt;
}

} // namespace snow
