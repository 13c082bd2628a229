/// @file world.hpp
/// @brief The World: entity allocator, component pools and singleton resources.
#pragma once

#include "ecs/component_pool.hpp"
#include "ecs/entity.hpp"
#include "ecs/error.hpp"
#include "ecs/host_memory.hpp"
#include "ecs/type_id.hpp"

#include <cstdint>
#include <memory>
#include <tuple>

namespace snow {

class World {
  public:
    World() = default;
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    World(World&&) = default;
    World& operator=(World&&) = default;

    /// Creates an entity; reuses freed slots with a bumped generation.
    [[nodiscard]] Entity create();
    /// Destroys an entity and all its components. Throws EcsError on a stale handle.
    void destroy(Entity e);
    /// True if the handle refers to a living entity of the same generation.
    [[nodiscard]] bool alive(Entity e) const;
    [[nodiscard]] std::size_t entity_count() const { return live_count_; }

    /// Adds (or replaces) a component. Throws EcsError on a stale handle.
    template <typename T, typename... Args>
    T& add(Entity e, Args&&... args) {
        check_alive(e, "add");
        return pool<T>().emplace(e, std::forward<Args>(args)...);
    }
    template <typename T>
    void remove(Entity e) {
        check_alive(e, "remove");
        if (auto* p = find_pool<T>()) {
            p->remove(e);
        }
    }
    template <typename T>
    [[nodiscard]] bool has(Entity e) const {
        const auto* p = find_pool<T>();
        return p != nullptr && p->contains(e);
    }
    /// Returns the component; throws EcsError if the entity is stale or lacks it.
    template <typename T>
    [[nodiscard]] T& get(Entity e) {
        check_alive(e, "get");
        T* c = find_pool<T>() ? find_pool<T>()->find(e) : nullptr;
        if (c == nullptr) {
            throw EcsError("entity has no such component");
        }
        return *c;
    }
    template <typename T>
    [[nodiscard]] const T& get(Entity e) const {
        return const_cast<World*>(this)->get<T>(e);
    }
    template <typename T>
    [[nodiscard]] T* try_get(Entity e) {
        auto* p = find_pool<T>();
        return p ? p->find(e) : nullptr;
    }
    template <typename T>
    [[nodiscard]] const T* try_get(Entity e) const {
        const auto* p = find_pool<T>();
        return p ? p->find(e) : nullptr;
    }
    /// Number of entities that have a T.
    template <typename T>
    [[nodiscard]] std::size_t count() const {
        const auto* p = find_pool<T>();
        return p ? p->size() : 0;
    }

    /// Calls fn(Entity, A&, B&...) for each entity with all listed components,
    /// in the dense order of the first type's pool (deterministic).
    template <typename First, typename... Rest, typename Fn>
    void each(Fn&& fn) {
        auto* first = find_pool<First>();
        if (first == nullptr) {
            return;
        }
        const auto& ents = first->entities();
        for (std::size_t i = 0; i < ents.size(); ++i) {
            const Entity e = ents[i];
            if ((has<Rest>(e) && ...)) {
                fn(e, first->components()[i], *find_pool<Rest>()->find(e)...);
            }
        }
    }
    template <typename First, typename... Rest, typename Fn>
    void each(Fn&& fn) const {
        const_cast<World*>(this)->each<First, Rest...>(
            [&](Entity e, const First& a, const Rest&... r) { fn(e, a, r...); });
    }

    /// Singleton resources (the flake pool, the clock, ...), owned by the World.
    template <typename T, typename... Args>
    T& set_resource(Args&&... args) {
        const std::uint32_t id = type_id<T>();
        if (id >= resources_.size()) {
            resources_.resize(id + 1);
        }
        resources_[id] = std::allocate_shared<T>(HostAllocator<T>{}, std::forward<Args>(args)...);
        return *static_cast<T*>(resources_[id].get());
    }
    template <typename T>
    [[nodiscard]] T* try_resource() {
        const std::uint32_t id = type_id<T>();
        return id < resources_.size() ? static_cast<T*>(resources_[id].get()) : nullptr;
    }
    template <typename T>
    [[nodiscard]] const T* try_resource() const {
        return const_cast<World*>(this)->try_resource<T>();
    }
    template <typename T>
    [[nodiscard]] T& resource() {
        T* r = try_resource<T>();
        if (r == nullptr) {
            throw EcsError("missing resource");
        }
        return *r;
    }
    template <typename T>
    [[nodiscard]] const T& resource() const {
        return const_cast<World*>(this)->resource<T>();
    }
    template <typename T>
    [[nodiscard]] bool has_resource() const {
        return try_resource<T>() != nullptr;
    }
    template <typename T>
    void erase_resource() {
        const std::uint32_t id = type_id<T>();
        if (id < resources_.size()) {
            resources_[id].reset();
        }
    }

    /// The pool of T (created on first use).
    template <typename T>
    [[nodiscard]] ComponentPool<T>& pool() {
        const std::uint32_t id = type_id<T>();
        if (id >= pools_.size()) {
            pools_.resize(id + 1);
        }
        if (!pools_[id]) {
            pools_[id] = std::make_unique<ComponentPool<T>>();
        }
        return *static_cast<ComponentPool<T>*>(pools_[id].get());
    }
    template <typename T>
    [[nodiscard]] ComponentPool<T>* find_pool() {
        const std::uint32_t id = type_id<T>();
        return id < pools_.size() ? static_cast<ComponentPool<T>*>(pools_[id].get()) : nullptr;
    }
    template <typename T>
    [[nodiscard]] const ComponentPool<T>* find_pool() const {
        return const_cast<World*>(this)->find_pool<T>();
    }

  private:
    void check_alive(Entity e, const char* what) const;

    Vector<std::uint32_t> generations_;
    Vector<std::uint8_t> live_;
    Vector<std::uint32_t> free_slots_;
    std::size_t live_count_ = 0;
    Vector<std::unique_ptr<ComponentPoolBase>> pools_; // HostAllocated
    // shared_ptr gives type-erased deletion without a virtual base for resources;
    // allocate_shared puts the object and its count in the host's memory.
    Vector<std::shared_ptr<void>> resources_;
};

} // namespace snow
