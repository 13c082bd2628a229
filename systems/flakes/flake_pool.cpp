#include "systems/flakes/flake_pool.hpp"

#include "systems/core/limits.hpp"
#include "systems/core/state_bytes.hpp"
#include "systems/flakes/held_wind.hpp"

#include <algorithm>

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
        return host_allocate(bytes, cache_line);
    }
    void* p = host_allocate(whole_pages(bytes), huge_page);
#if defined(__linux__)
    (void)madvise(p, whole_pages(bytes), MADV_HUGEPAGE); // refused: 4 KiB pages, same data
#endif
    return p;
}

void free_pool_array(void* p, std::size_t bytes) noexcept {
    if (bytes < huge_page) {
        host_free(p, bytes, cache_line);
    } else {
        host_free(p, whole_pages(bytes), huge_page);
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

namespace {

/// The per-slot arrays up to slot_end; slots above it are as reset() left them.
template <typename Io, typename Pool>
void slot_arrays(Io& io, Pool& f) {
    for (auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz, &f.k_over_m, &f.size}) {
        io.block(a->data(), f.slot_end);
    }
    io.block(f.mass_units.data(), f.slot_end);
    io.block(f.id.data(), f.slot_end);
    if (f.holds_wind()) {
        for (auto& a : f.held_wind) {
            io.block(a.data(), f.slot_end);
        }
    }
}

/// Alive slots hold finite values and a mass within limits, free ones are
/// parked, and the free stack lists each free slot once: what a run leaves.
void check_slots(const ByteReader& in, const FlakePool& f) {
    Vector<bool> is_free(f.capacity(), false);
    for (const std::uint32_t s : f.free_stack) {
        in.require(s < f.capacity() && !is_free[s], "lists a free slot twice or past the pool");
        is_free[s] = true;
    }
    std::uint32_t alive = 0;
    for (std::uint32_t i = 0; i < f.capacity(); ++i) {
        const bool live = f.mass_units[i] != 0;
        in.require(live != is_free[i], "has a slot both alive and free (or neither)");
        if (!live) {
            continue;
        }
        ++alive;
        in.require(f.mass_units[i] <= max_flake_units, "has a flake heavier than any flake can be");
        for (const auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz, &f.k_over_m, &f.size}) {
            in.require(std::isfinite((*a)[i]), "has a flake with a non-finite value");
        }
    }
    in.require(alive == f.alive && f.max_alive >= alive, "miscounts its alive flakes");
}

} // namespace

void save_state(ByteWriter& out, const FlakePool& f) {
    out(f.capacity());
    out(f.holds_wind());
    for (const std::uint32_t v : {f.alive, f.max_alive, f.slot_end, f.next_id}) {
        out(v);
    }
    slot_arrays(out, f);
    out(f.free_stack);
}

void load_state(ByteReader& in, FlakePool& f) {
    std::uint32_t capacity = 0;
    bool held = false;
    in(capacity);
    in(held);
    in.require(capacity == f.capacity(), "is for a flake pool of another size");
    f.reset(capacity);
    f.hold_wind(held);
    in(f.alive);
    in(f.max_alive);
    in(f.slot_end);
    in(f.next_id);
    in.require(f.slot_end <= capacity, "has slots past the pool");
    slot_arrays(in, f);
    in(f.free_stack);
    check_slots(in, f);
    f.free_stack.reserve(capacity); // release() never allocates
}

Invalid validate(const FlakeSpec& f) {
    return check_fields("flake", flake_fields, f);
}

void hash_state(StateHasher& h, const FlakePool& f) {
    h.value(f.capacity());
    for (const std::uint32_t v : {f.alive, f.max_alive, f.slot_end, f.next_id}) {
        h.value(v);
    }
    for (std::uint32_t i = 0; i < f.slot_end; ++i) {
        if (!f.is_alive(i)) {
            continue;
        }
        h.value(i);
        for (const auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz, &f.k_over_m, &f.size}) {
            h.value((*a)[i]);
        }
        h.value(f.mass_units[i]);
        h.value(f.id[i]);
        if (f.holds_wind()) {
            for (const auto& a : f.held_wind) {
                h.value(a[i]);
            }
        }
    }
    h.span(std::span<const std::uint32_t>(f.free_stack));
}

} // namespace snow
