/// @file surface_list.hpp
/// @brief Every snow heightfield of a simulation (declared surfaces and
/// covers) with a stable name, and what lies on each: what snow_run reports
/// and exports.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

enum class SurfaceKind : std::uint8_t { surface, cover };

[[nodiscard]] std::string_view kind_name(SurfaceKind k);

struct NamedSurface {
    Entity entity;
    SurfaceKind kind = SurfaceKind::surface;
    /// "surface_<entity index>" or "cover_<entity index>": the same for the
    /// same scene, usable as a file stem and a glTF node name.
    std::string name;
    const SnowSurface* surface = nullptr;
};

/// Every SnowSurface entity, by ascending entity index.
[[nodiscard]] std::vector<NamedSurface> named_surfaces(const Simulation& sim);

/// What lies on one surface. Void cells (no geometry) count nowhere.
struct SurfaceStats {
    std::uint64_t cells = 0; ///< cells that are not void
    std::uint64_t settled_units = 0;
    double mean_depth_m = 0.0; ///< over the non-void cells (0 when there are none)
    double max_depth_m = 0.0;
};

[[nodiscard]] SurfaceStats surface_stats(const SnowSurface& s);

} // namespace snow
