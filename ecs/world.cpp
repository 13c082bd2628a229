#include "ecs/world.hpp"

namespace snow {

Entity World::create() {
    std::uint32_t index = 0;
    if (!free_slots_.empty()) {
        // LIFO reuse keeps creation order deterministic for a given history.
        index = free_slots_.back();
        free_slots_.pop_back();
    } else {
        if (generations_.size() >= Entity::max_entities) {
            throw EcsError("entity limit reached (" + std::to_string(Entity::max_entities) + ")");
        }
        index = static_cast<std::uint32_t>(generations_.size());
        generations_.push_back(0);
        live_.push_back(0);
    }
    live_[index] = 1;
    ++live_count_;
    return Entity::make(index, generations_[index]);
}

bool World::alive(Entity e) const {
    if (e.is_null()) {
        return false;
    }
    const std::uint32_t i = e.index();
    return i < generations_.size() && live_[i] != 0 &&
           (generations_[i] & Entity::generation_mask) == e.generation();
}

void World::check_alive(Entity e, const char* what) const {
    if (!alive(e)) {
        throw EcsError(std::string("World::") + what + ": stale or null entity handle");
    }
}

void World::destroy(Entity e) {
    check_alive(e, "destroy");
    for (auto& p : pools_) {
        if (p) {
            p->remove(e);
        }
    }
    const std::uint32_t i = e.index();
    live_[i] = 0;
    --live_count_;
    // A slot whose generation would wrap is retired, so an old handle can never
    // match a new entity.
    if (generations_[i] + 1 > Entity::generation_mask) {
        return;
    }
    ++generations_[i];
    free_slots_.push_back(i);
}

} // namespace snow
