#include "ecs/host_memory.hpp"

#include <atomic>

#include <snow/error.hpp>

namespace snow {

namespace {

void* default_allocate(std::size_t size, std::size_t alignment, void*) {
    return ::operator new (size, std::align_val_t{alignment}, std::nothrow);
}

void default_free(void* p, std::size_t size, std::size_t alignment, void*) {
    ::operator delete (p, size, std::align_val_t{alignment});
}

Allocator current{default_allocate, default_free, nullptr};
// Threads allocate at once (tasks of different Simulations), so the counts are atomic.
std::atomic<std::size_t> bytes{0};
std::atomic<std::size_t> live{0};

/// The one rule of set_allocator and reset_allocator.
void replace(const Allocator& next, const char* call) {
    if (next.allocate == nullptr || next.free == nullptr) {
        throw SimulationError(std::string(call) + "(allocator)", next.allocate == nullptr
                                                                     ? "has no allocate function"
                                                                     : "has no free function");
    }
    if (const std::size_t held = live.load(); held > 0) {
        throw SimulationError(std::string(call) + ": the library still holds " +
                              std::to_string(held) + " block(s) of " +
                              std::to_string(bytes.load()) +
                              " bytes from the allocator before; destroy every Simulation first "
                              "(a block must go back to the allocator that gave it)");
    }
    current = next;
}

} // namespace

void* host_allocate(std::size_t size, std::size_t alignment) {
    void* p = current.allocate(size, alignment, current.user);
    if (p == nullptr) {
        throw std::bad_alloc();
    }
    bytes.fetch_add(size, std::memory_order_relaxed);
    live.fetch_add(1, std::memory_order_relaxed);
    return p;
}

void host_free(void* p, std::size_t size, std::size_t alignment) noexcept {
    if (p == nullptr) {
        return;
    }
    current.free(p, size, alignment, current.user);
    bytes.fetch_sub(size, std::memory_order_relaxed);
    live.fetch_sub(1, std::memory_order_relaxed);
}

void set_allocator(const Allocator& allocator) {
    replace(allocator, "set_allocator");
}

void reset_allocator() {
    replace(Allocator{default_allocate, default_free, nullptr}, "reset_allocator");
}

std::size_t allocated_bytes() {
    return bytes.load();
}

std::size_t live_allocations() {
    return live.load();
}

} // namespace snow
