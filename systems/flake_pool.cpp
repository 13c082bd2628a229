#include "systems/flake_pool.hpp"

#include "systems/held_wind.hpp"

#include <algorithm>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace snow {

namespace {

constexpr std::size_t cache_line = 64;
constexpr std::size_t huge_page = std::size_t{2} << 20;

std::size_t whole_pages(std::size_t bytes) {
    return (bytes + huge_page - 1) / huge_page * huge_page;
}

} // namespace

void* allocate_pool_array(std::size_t bytes) {
    if (bytes < huge_page) {
        return ::operator new (bytes, std::align_val_t{cache_line});
    }
    void* p = ::operator new (whole_pages(bytes), std::align_val_t{huge_page});
#if defined(__linux__)
    (void)madvise(p, whole_pages(bytes), MADV_HUGEPAGE); // refused: 4 KiB pages, same data
#endif
    return p;
}

void free_pool_array(void* p, std::size_t bytes) noexcept {
    if (bytes < huge_page) {
        ::operator delete (p, bytes, std::align_val_t{cache_line});
    } else {
        ::operator delete (p, whole_pages(bytes), std::align_val_t{huge_page});
    }
}

void FlakePool::reset(std::uint32_t capacity) {
    for (auto* v : {&px, &pz, &vx, &vy, &vz, &k_over_m, &size}) {
        v->assign(capacity, 0.0f);
    }
    py.assign(capacity, parked_y);
    mass_units.assign(capacity, 0);
    id.assign(capacity, 0);
    hold_wind(holds_wind());
    free_stack.resize(capacity);
    // Highest slot at the bottom so slot 0 is handed out first.
    for (std::uint32_t i = 0; i < capacity; ++i) {
        free_stack[i] = capacity - 1 - i;
    }
    alive = 0;
    max_alive = 0;
    slot_end = 0;
    next_id = 0;
}

void FlakePool::hold_wind(bool on) {
    for (auto& a : held_wind) {
        if (on) {
            a.assign(capacity(), held_wind_unset);
        } else {
            a = PoolArray<std::int16_t>();
        }
    }
}

bool FlakePool::acquire(std::uint32_t& slot) {
    if (free_stack.empty()) {
        return false;
    }
    slot = free_stack.back();
    free_stack.pop_back();
    id[slot] = next_id++;
    if (holds_wind()) {
        held_wind[0][slot] = held_wind_unset;
    }
    ++alive;
    max_alive = std::max(max_alive, alive);
    slot_end = std::max(slot_end, slot + 1);
    return true;
}

std::uint64_t FlakePool::airborne_units() const {
    std::uint64_t sum = 0;
    for (std::uint32_t i = 0; i < slot_end; ++i) {
        sum += mass_units[i];
    }
    return sum;
}

} // namespace snow
