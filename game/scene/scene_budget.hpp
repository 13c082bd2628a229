/// @file scene_budget.hpp
/// @brief Adds up the work a scene declares against a WorkBudget
/// (docs/scenes.md#work-budget), before anything is allocated.
#pragma once

#include <snow/scene.hpp>

#include <cstdint>
#include <string>

namespace snow {

/// One kind of work a WorkBudget bounds.
struct WorkKind {
    std::uint64_t WorkBudget::*limit;
    const char* name; ///< the WorkBudget member, for the error
    const char* unit; ///< what is counted ("snow cells")
};

inline constexpr WorkKind snow_cells_work{&WorkBudget::snow_cells, "snow_cells", "snow cells"};
inline constexpr WorkKind surfaces_work{&WorkBudget::surfaces, "surfaces", "snow surfaces"};
inline constexpr WorkKind collider_triangles_work{&WorkBudget::collider_triangles,
                                                  "collider_triangles", "mesh collider triangles"};
inline constexpr WorkKind bodies_work{&WorkBudget::bodies, "bodies", "moving bodies"};
inline constexpr WorkKind flakes_work{&WorkBudget::flakes, "flakes", "flakes in the pool"};
inline constexpr WorkKind field_cells_work{&WorkBudget::field_cells, "field_cells",
                                           "wind field cells"};
inline constexpr WorkKind field_cell_sweeps_work{
    &WorkBudget::field_cell_sweeps, "field_cell_sweeps", "field cell sweeps per solver step"};
inline constexpr WorkKind occlusion_texels_work{&WorkBudget::occlusion_texels, "occlusion_texels",
                                                "sky map texels"};

/// The running totals of one scene's declared work.
class WorkTally {
  public:
    explicit WorkTally(const WorkBudget& budget) : budget_(budget) {}

    /// Adds `amount` of `kind`, declared by `field`; throws SceneError naming
    /// `field`, the total and the budget when the total passes it.
    void add(const WorkKind& kind, std::uint64_t amount, const std::string& field);

  private:
    WorkBudget budget_;
    WorkBudget total_{0, 0, 0, 0, 0, 0, 0, 0};
};

} // namespace snow
