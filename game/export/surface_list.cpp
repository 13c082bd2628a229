#include "game/export/surface_list.hpp"
#include "systems/api/simulation_internals.hpp"

#include <algorithm>

namespace snow {

std::string_view kind_name(SurfaceKind k) {
    return k == SurfaceKind::cover ? "cover" : "surface";
}

std::vector<NamedSurface> named_surfaces(const Simulation& sim) {
    const World& w = world_of(sim);
    std::vector<NamedSurface> out;
    w.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        const SurfaceKind kind = w.has<SnowCover>(e) ? SurfaceKind::cover : SurfaceKind::surface;
        out.push_back(
            {e, kind, std::string(kind_name(kind)) + "_" + std::to_string(e.index()), &s});
    });
    std::sort(out.begin(), out.end(), [](const NamedSurface& a, const NamedSurface& b) {
        return a.entity.index() < b.entity.index();
    });
    return out;
}

SurfaceStats surface_stats(const SnowSurface& s) {
    SurfaceStats st;
    std::int64_t levels = 0, max_levels = 0;
    for (std::size_t i = 0; i < s.cell_count(); ++i) {
        if (!s.is_void(i)) {
            ++st.cells;
            st.settled_units += s.snow[i];
            levels += s.depth_levels(i);
            max_levels = std::max(max_levels, s.depth_levels(i));
        }
    }
    const double unit = s.unit_height;
    st.mean_depth_m =
        st.cells > 0 ? static_cast<double>(levels) * unit / static_cast<double>(st.cells) : 0.0;
    st.max_depth_m = static_cast<double>(max_levels) * unit;
    return st;
}

} // namespace snow
