/// @file component_pool.hpp
/// @brief Dense component storage over a sparse set (EnTT style).
#pragma once

#include "ecs/entity.hpp"
#include "ecs/host_memory.hpp"

#include <cstdint>
#include <utility>

namespace snow {

/// Type-erased base so the World can remove every component of a destroyed
/// entity; pools live in the host's memory.
class ComponentPoolBase : public HostAllocated {
  public:
    virtual ~ComponentPoolBase() = default;
    virtual void remove(Entity e) = 0;
    [[nodiscard]] virtual bool contains(Entity e) const = 0;
    [[nodiscard]] virtual std::size_t size() const = 0;
};

/// Sparse set: sparse[index] -> dense position; dense arrays hold entities and
/// components side by side. Removal swaps with the last element, so iteration
/// order is insertion order until the first removal (deterministic either way).
template <typename T>
class ComponentPool final : public ComponentPoolBase {
  public:
    static constexpr std::uint32_t absent = 0xFFFFFFFFu;

    template <typename... Args>
    T& emplace(Entity e, Args&&... args) {
        const std::uint32_t i = e.index();
        if (i >= sparse_.size()) {
            sparse_.resize(i + 1, absent);
        }
        if (sparse_[i] != absent) {
            dense_[sparse_[i]] = T{std::forward<Args>(args)...};
            return dense_[sparse_[i]];
        }
        sparse_[i] = static_cast<std::uint32_t>(dense_.size());
        entities_.push_back(e);
        dense_.push_back(T{std::forward<Args>(args)...});
        return dense_.back();
    }

    void remove(Entity e) override {
        if (!contains(e)) {
            return;
        }
        const std::uint32_t pos = sparse_[e.index()];
        const std::uint32_t last = static_cast<std::uint32_t>(dense_.size() - 1);
        if (pos != last) {
            dense_[pos] = std::move(dense_[last]);
            entities_[pos] = entities_[last];
            sparse_[entities_[pos].index()] = pos;
        }
        dense_.pop_back();
        entities_.pop_back();
        sparse_[e.index()] = absent;
    }

    [[nodiscard]] bool contains(Entity e) const override {
        const std::uint32_t i = e.index();
        return !e.is_null() && i < sparse_.size() && sparse_[i] != absent &&
               entities_[sparse_[i]] == e;
    }

    [[nodiscard]] T* find(Entity e) { return contains(e) ? &dense_[sparse_[e.index()]] : nullptr; }
    [[nodiscard]] const T* find(Entity e) const {
        return contains(e) ? &dense_[sparse_[e.index()]] : nullptr;
    }

    [[nodiscard]] std::size_t size() const override { return dense_.size(); }
    [[nodiscard]] const Vector<Entity>& entities() const { return entities_; }
    [[nodiscard]] Vector<T>& components() { return dense_; }
    [[nodiscard]] const Vector<T>& components() const { return dense_; }

  private:
    Vector<std::uint32_t> sparse_;
    Vector<Entity> entities_;
    Vector<T> dense_;
};

} // namespace snow
