/// @file counted_new.hpp
/// @brief Test support: replaces the global operator new and delete with
/// versions that count calls while `counting_new` is set, to prove that
/// code allocates nothing. Replacements are program-wide: include this in
/// exactly one source file of a test executable.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace snow::test {

inline std::atomic<bool> counting_new{false};
inline std::atomic<std::uint64_t> new_calls{0};

/// malloc, or aligned_alloc for alignments beyond max_align_t (both free with std::free).
inline void* malloc_aligned(std::size_t size, std::size_t alignment) noexcept {
    size = size == 0 ? 1 : size;
    if (alignment <= alignof(std::max_align_t)) {
        return std::malloc(size);
    }
    return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}

inline void* counted_new(std::size_t size, std::size_t alignment) noexcept {
    if (counting_new.load(std::memory_order_relaxed)) {
        new_calls.fetch_add(1, std::memory_order_relaxed);
    }
    return malloc_aligned(size, alignment);
}

inline void* counted_new_or_throw(std::size_t size, std::size_t alignment) {
    void* p = counted_new(size, alignment);
    if (p == nullptr) {
        throw std::bad_alloc();
    }
    return p;
}

} // namespace snow::test

// Every replaceable allocation form counts; every deallocation form frees.
void* operator new(std::size_t n) {
    return snow::test::counted_new_or_throw(n, 0);
}
void* operator new[](std::size_t n) {
    return snow::test::counted_new_or_throw(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a) {
    return snow::test::counted_new_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return snow::test::counted_new_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    return snow::test::counted_new(n, 0);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    return snow::test::counted_new(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return snow::test::counted_new(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return snow::test::counted_new(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
