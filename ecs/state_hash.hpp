/// @file state_hash.hpp
/// @brief 64-bit FNV-1a over a canonical byte view of simulation state.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

namespace snow {

class StateHasher {
  public:
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) {
            h_ ^= p[i];
            h_ *= 0x100000001B3ull;
        }
    }
    /// Hashes a trivially copyable value by its bytes (floats: exact bits).
    template <typename T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof(T));
    }
    template <typename T>
    void span(std::span<const T> s) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(static_cast<std::uint64_t>(s.size()));
        bytes(s.data(), s.size_bytes());
    }
    [[nodiscard]] std::uint64_t digest() const { return h_; }

  private:
    std::uint64_t h_ = 0xCBF29CE484222325ull;
};

} // namespace snow
