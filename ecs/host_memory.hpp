/// @file host_memory.hpp
/// @brief Every allocation of the simulation library goes through the host's
/// Allocator (<snow/allocator.hpp>): containers take HostAllocator (Vector,
/// String), objects snow creates whole derive HostAllocated, and resources
/// are made with std::allocate_shared over HostAllocator (ecs/world.hpp).
#pragma once

#include <cstddef>
#include <new>
#include <string>
#include <vector>

#include <snow/allocator.hpp>

namespace snow {

/// `size` bytes aligned to `alignment` from the host's allocator, counted;
/// throws std::bad_alloc when it gives none.
[[nodiscard]] void* host_allocate(std::size_t size, std::size_t alignment);
/// Gives a block of host_allocate back, with the size and alignment it was asked for.
void host_free(void* p, std::size_t size, std::size_t alignment) noexcept;

/// The standard allocator over host_allocate (stateless: every instance
/// frees what any other allocated).
template <typename T>
struct HostAllocator {
    using value_type = T;

    HostAllocator() = default;
    template <typename U>
    HostAllocator(const HostAllocator<U>&) noexcept {}

    [[nodiscard]] T* allocate(std::size_t n) {
        return static_cast<T*>(host_allocate(n * sizeof(T), alignof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { host_free(p, n * sizeof(T), alignof(T)); }
    template <typename U>
    bool operator==(const HostAllocator<U>&) const noexcept {
        return true;
    }
};

template <typename T>
using Vector = std::vector<T, HostAllocator<T>>;
using String = std::basic_string<char, std::char_traits<char>, HostAllocator<char>>;

/// Base of the classes snow creates with new and deletes through a pointer
/// (the Simulation's pimpl, the World's component pools, the built-in job
/// pool, in-memory snapshots): their new and delete go through the host's
/// allocator. A class deleted through a base pointer needs a virtual
/// destructor, so delete passes the size of what was made.
struct HostAllocated {
    static void* operator new(std::size_t size) {
        return host_allocate(size, __STDCPP_DEFAULT_NEW_ALIGNMENT__);
    }
    static void* operator new(std::size_t size, std::align_val_t alignment) {
        return host_allocate(size, static_cast<std::size_t>(alignment));
    }
    static void operator delete(void* p, std::size_t size) noexcept {
        host_free(p, size, __STDCPP_DEFAULT_NEW_ALIGNMENT__);
    }
    static void operator delete(void* p, std::size_t size, std::align_val_t alignment) noexcept {
        host_free(p, size, static_cast<std::size_t>(alignment));
    }
};

} // namespace snow
