#include "game/scene/scene_budget.hpp"

#include "game/scene/scene_error.hpp"

#include <limits>

namespace snow {

void WorkTally::add(const WorkKind& kind, std::uint64_t amount, const std::string& field) {
    std::uint64_t& total = total_.*kind.limit;
    const std::uint64_t limit = budget_.*kind.limit;
    total = amount > std::numeric_limits<std::uint64_t>::max() - total
                ? std::numeric_limits<std::uint64_t>::max()
                : total + amount;
    if (total > limit) {
        scene_fail(field, "brings the scene to " + std::to_string(total) + " " + kind.unit +
                              "; its work budget allows " + std::to_string(limit) +
                              " (a host raises SceneOverrides::budget." + kind.name +
                              ", docs/scenes.md#work-budget)");
    }
}

} // namespace snow
