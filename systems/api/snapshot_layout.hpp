/// @file snapshot_layout.hpp
/// @brief The frame around a byte snapshot's payload (docs/embedding.md
/// "Snapshots"): magic, format version and payload length before it, a
/// checksum of everything before the checksum after it. Simulation::save_bytes
/// writes it and load_bytes checks it (snapshot_bytes.cpp); the snapshot
/// fuzz target re-frames mutated payloads so that they reach the records.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace snow {

inline constexpr std::array<char, 8> snapshot_magic{'S', 'N', 'O', 'W', 'S', 'N', 'A', 'P'};
/// 3: a wind field's settings say whether it is a tunnel, its transport's
/// how fast it runs forward and over what length its flux adjusts. 2: the
/// transport's settings are its roughness and read height (the saltation
/// flux); format 1 held a threshold speed, a rate and a fraction.
inline constexpr std::uint32_t snapshot_format = 3;
/// Bytes before the payload: the magic, the format version, the payload length.
inline constexpr std::size_t snapshot_header_bytes = snapshot_magic.size() + 4 + 8;
/// Offset of the payload length (a little-endian uint64) in the header.
inline constexpr std::size_t snapshot_length_at = snapshot_magic.size() + 4;
inline constexpr std::size_t snapshot_checksum_bytes = 8;

/// The checksum the snapshot's last 8 bytes hold, over every byte before them.
[[nodiscard]] std::uint64_t snapshot_checksum(std::span<const std::byte> framed);

} // namespace snow
