#include "game/play/snow_readout.hpp"

namespace snow {

std::optional<SnowColumn> snow_column(const World& world, float x, float z, float below) {
    std::optional<SnowColumn> best;
    world.each<SnowSurface>([&](Entity, const SnowSurface& s) {
        std::uint32_t ix = 0, iz = 0;
        if (!s.cell_at(x, z, ix, iz) || s.is_void(s.index(ix, iz))) {
            return;
        }
        const std::size_t i = s.index(ix, iz);
        const float base = s.height(s.base_level[i]);
        if (base <= below && (!best || base > best->base)) {
            best = SnowColumn{base, s.depth(i)};
        }
    });
    return best;
}

const SnowSurface* ground_surface(const World& world) {
    const SnowSurface* best = nullptr;
    world.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        const SurfaceOf* of = world.try_get<SurfaceOf>(e);
        const bool ground = world.has<SnowCover>(e) || (of != nullptr && of->owner.is_null());
        if (ground && (best == nullptr || s.cell_count() > best->cell_count())) {
            best = &s;
        }
    });
    return best;
}

double mean_depth(const SnowSurface& s) {
    std::int64_t levels = 0, cells = 0;
    for (std::size_t i = 0; i < s.cell_count(); ++i) {
        if (!s.is_void(i)) {
            levels += s.depth_levels(i);
            ++cells;
        }
    }
    return cells > 0 ? static_cast<double>(levels) * s.unit_height / static_cast<double>(cells)
                     : 0.0;
}

} // namespace snow
