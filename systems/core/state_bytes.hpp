/// @file state_bytes.hpp
/// @brief The byte form of simulation state (snapshots): a writer and a
/// reader over the same field lists, so a type's record is written once
/// (a template over either) beside the type. Little-endian IEEE bytes, the
/// same on every platform snow runs on (x86-64, aarch64).
#pragma once

#include "ecs/error.hpp"
#include "ecs/state_hash.hpp"

#include <glm/vec3.hpp>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace snow {

static_assert(std::endian::native == std::endian::little,
              "snapshots are written in the machine's byte order, which must be little-endian");

/// Scalars written as their bytes: integers, floats, enums. bool is one
/// byte that must read back as 0 or 1.
/// Plain structs of integers (no padding, every bit pattern valid) too.
template <typename T>
concept ByteScalar = std::is_arithmetic_v<T> || std::is_enum_v<T> ||
    (std::is_trivially_copyable_v<T>&& std::has_unique_object_representations_v<T>);

class ByteWriter {
  public:
    static constexpr bool reading = false;

    ByteWriter() = default;
    /// Writes into `hash` instead of a buffer: a type whose state hash covers
    /// exactly its record hashes through the record (one field list for both).
    explicit ByteWriter(StateHasher& hash) : hash_(&hash) {}

    template <ByteScalar T>
    void operator()(const T& v) {
        put(&v, sizeof(T));
    }
    void operator()(const glm::vec3& v) {
        (*this)(v.x);
        (*this)(v.y);
        (*this)(v.z);
    }
    /// A count, then the elements (scalars as one block).
    template <typename T, typename A>
    void operator()(const std::vector<T, A>& v) {
        (*this)(static_cast<std::uint64_t>(v.size()));
        if constexpr (ByteScalar<T>) {
            put(v.data(), v.size() * sizeof(T));
        } else {
            for (const T& e : v) {
                (*this)(e);
            }
        }
    }
    template <typename T>
    void operator()(const std::optional<T>& v) {
        (*this)(v.has_value());
        if (v) {
            (*this)(*v);
        }
    }
    /// `n` scalars from `p`, no count (the reader knows it).
    template <ByteScalar T>
    void block(const T* p, std::size_t n) {
        put(p, n * sizeof(T));
    }
    /// A record's place in the stream (the reader names it in its errors).
    void record(const std::string&) {}

    [[nodiscard]] std::vector<std::byte>& bytes() { return bytes_; }

  private:
    void put(const void* p, std::size_t n) {
        if (hash_ != nullptr) {
            hash_->bytes(p, n);
            return;
        }
        const auto* b = static_cast<const std::byte*>(p);
        bytes_.insert(bytes_.end(), b, b + n);
    }
    StateHasher* hash_ = nullptr;
    std::vector<std::byte> bytes_;
};

/// Reads what a ByteWriter wrote. Every read is bounds-checked; a count that
/// would pass the end, a bool that is not 0 or 1, an enum past `enum_end`
/// throw SimulationError naming the record ("snapshot.surface[2] ...").
class ByteReader {
  public:
    static constexpr bool reading = true;

    explicit ByteReader(std::span<const std::byte> bytes) : bytes_(bytes) {}

    template <ByteScalar T>
    void operator()(T& v) {
        if constexpr (std::is_same_v<T, bool>) {
            std::uint8_t b = 0;
            take(&b, 1);
            if (b > 1) {
                fail("holds a flag that is neither 0 nor 1");
            }
            v = b != 0;
        } else {
            take(&v, sizeof(T));
        }
    }
    void operator()(glm::vec3& v) {
        (*this)(v.x);
        (*this)(v.y);
        (*this)(v.z);
    }
    template <typename T, typename A>
    void operator()(std::vector<T, A>& v) {
        std::uint64_t n = 0;
        (*this)(n);
        // Each element takes at least one byte (a scalar its size): a count
        // past the end is corrupt, and is refused before anything is
        // allocated for it.
        if (n > left() / (ByteScalar<T> ? sizeof(T) : 1)) {
            fail("holds a count past the end of the bytes");
        }
        v.resize(static_cast<std::size_t>(n));
        if constexpr (ByteScalar<T> && !std::is_same_v<T, bool>) {
            take(v.data(), v.size() * sizeof(T));
        } else {
            for (T& e : v) {
                (*this)(e);
            }
        }
    }
    template <typename T>
    void operator()(std::optional<T>& v) {
        bool has = false;
        (*this)(has);
        if (!has) {
            v.reset();
            return;
        }
        v.emplace();
        (*this)(*v);
    }
    template <ByteScalar T>
    requires(!std::is_same_v<T, bool>) void block(T* p, std::size_t n) { take(p, n * sizeof(T)); }
    /// Names the record read next in errors: `name`, or `name[index]`.
    void record(const char* name, std::optional<std::uint64_t> index = {}) {
        record_ = name;
        index_ = index;
    }

    /// Throws unless `ok`, naming the record and `problem`.
    void require(bool ok, const char* problem) const {
        if (!ok) {
            fail(problem);
        }
    }
    /// An enum read as its underlying value must lie below `end`.
    template <typename E>
    void require_below(E v, E end) const {
        require(static_cast<std::underlying_type_t<E>>(v) <
                    static_cast<std::underlying_type_t<E>>(end),
                "holds an unknown kind");
    }
    [[nodiscard]] std::size_t left() const { return bytes_.size() - at_; }
    [[noreturn]] void fail(const std::string& problem) const {
        std::string field = "snapshot";
        if (*record_ != '\0') {
            field.append(".").append(record_);
        }
        if (index_) {
            field.append("[").append(std::to_string(*index_)).append("]");
        }
        throw SimulationError(field, problem);
    }

  private:
    void take(void* p, std::size_t n) {
        if (n > left()) {
            fail("is cut short (the bytes end inside it)");
        }
        if (n > 0) {
            std::memcpy(p, bytes_.data() + at_, n);
        }
        at_ += n;
    }
    std::span<const std::byte> bytes_;
    std::size_t at_ = 0;
    // The name of the record, formatted only when an error needs it.
    const char* record_ = "";
    std::optional<std::uint64_t> index_;
};

/// True when every value is finite (a state array a run could have produced).
template <typename T, typename A>
[[nodiscard]] bool all_finite(const std::vector<T, A>& v) {
    for (const T x : v) {
        if (!std::isfinite(x)) {
            return false;
        }
    }
    return true;
}

} // namespace snow
