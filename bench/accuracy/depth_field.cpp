// Depth fields and their comparison (method in docs/accuracy.md "Scene level").
#include "bench/accuracy/depth_field.hpp"
#include "systems/api/simulation_internals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace snow::accuracy {

namespace {

/// Cell index along one axis for coordinate u, clamped to [0, n).
std::uint32_t clamped_cell(double u, float origin, float cell, std::uint32_t n) {
    const double f = std::floor((u - origin) / cell);
    return static_cast<std::uint32_t>(std::clamp(f, 0.0, static_cast<double>(n - 1)));
}

/// Volume-weighted centroid (x, z) of a surface; false when it has no snow.
bool centroid(const SurfaceDepth& s, double& cx, double& cz) {
    double sum = 0.0, sx = 0.0, sz = 0.0;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const double d = s.depth[static_cast<std::size_t>(iz) * s.nx + ix];
            sum += d;
            sx += d * (s.x0 + (ix + 0.5) * s.cell);
            sz += d * (s.z0 + (iz + 0.5) * s.cell);
        }
    }
    if (sum <= 0.0) {
        return false;
    }
    cx = sx / sum;
    cz = sz / sum;
    return true;
}

/// Sums over the blocks of one surface pair.
struct BlockSums {
    double abs_volume_error = 0.0; ///< Σ |run − ref| · block area
    double ref_volume = 0.0;
    double area = 0.0;
    double linf = 0.0;
};

void add_blocks(const SurfaceDepth& run, const SurfaceDepth& ref, float block, BlockSums& out) {
    const auto k = static_cast<std::uint32_t>(std::max(1.0f, std::round(block / ref.cell)));
    const double cell_area = static_cast<double>(ref.cell) * ref.cell;
    for (std::uint32_t bz = 0; bz < ref.nz; bz += k) {
        for (std::uint32_t bx = 0; bx < ref.nx; bx += k) {
            double sum_run = 0.0, sum_ref = 0.0;
            std::uint32_t cells = 0;
            for (std::uint32_t iz = bz; iz < std::min(bz + k, ref.nz); ++iz) {
                for (std::uint32_t ix = bx; ix < std::min(bx + k, ref.nx); ++ix) {
                    const double x = ref.x0 + (ix + 0.5) * ref.cell;
                    const double z = ref.z0 + (iz + 0.5) * ref.cell;
                    sum_run += run.sample(x, z);
                    sum_ref += ref.depth[static_cast<std::size_t>(iz) * ref.nx + ix];
                    ++cells;
                }
            }
            const double err = std::abs(sum_run - sum_ref) / cells; // block-mean depth error
            out.abs_volume_error += err * cells * cell_area;
            out.ref_volume += sum_ref * cell_area;
            out.area += cells * cell_area;
            out.linf = std::max(out.linf, err);
        }
    }
}

} // namespace

double SurfaceDepth::sample(double x, double z) const {
    return depth[static_cast<std::size_t>(clamped_cell(z, z0, cell, nz)) * nx +
                 clamped_cell(x, x0, cell, nx)];
}

double SurfaceDepth::volume() const {
    double sum = 0.0;
    for (const double d : depth) {
        sum += d;
    }
    return sum * cell * cell;
}

DepthField capture_depth(const Simulation& sim) {
    DepthField f;
    world_of(sim).each<SnowSurface>([&](Entity, const SnowSurface& s) {
        SurfaceDepth d{s.x0, s.z0, s.cell, s.nx, s.nz, {}};
        d.depth.reserve(s.snow.size());
        for (const std::uint32_t units : s.snow) {
            d.depth.push_back(static_cast<double>(units) * s.unit_height);
        }
        f.surfaces.push_back(std::move(d));
    });
    return f;
}

DepthField mean_field(const std::vector<DepthField>& fields) {
    if (fields.empty()) {
        throw std::invalid_argument("mean_field: no fields");
    }
    DepthField mean = fields.front();
    for (std::size_t k = 1; k < fields.size(); ++k) {
        if (fields[k].surfaces.size() != mean.surfaces.size()) {
            throw std::invalid_argument("mean_field: fields have different surfaces");
        }
        for (std::size_t s = 0; s < mean.surfaces.size(); ++s) {
            const auto& add = fields[k].surfaces[s].depth;
            auto& acc = mean.surfaces[s].depth;
            if (add.size() != acc.size()) {
                throw std::invalid_argument("mean_field: fields have different grids");
            }
            for (std::size_t i = 0; i < acc.size(); ++i) {
                acc[i] += add[i];
            }
        }
    }
    for (SurfaceDepth& s : mean.surfaces) {
        for (double& d : s.depth) {
            d /= static_cast<double>(fields.size());
        }
    }
    return mean;
}

DepthError compare_depth(const DepthField& run, const DepthField& ref, float block) {
    if (run.surfaces.size() != ref.surfaces.size()) {
        throw std::invalid_argument("compare_depth: the runs have different surface counts");
    }
    BlockSums sums;
    double shift_weighted = 0.0, shift_weight = 0.0, run_volume = 0.0;
    for (std::size_t s = 0; s < ref.surfaces.size(); ++s) {
        const SurfaceDepth& a = run.surfaces[s];
        const SurfaceDepth& b = ref.surfaces[s];
        add_blocks(a, b, block, sums);
        run_volume += a.volume();
        double ax = 0.0, az = 0.0, bx = 0.0, bz = 0.0;
        if (centroid(a, ax, az) && centroid(b, bx, bz)) {
            shift_weighted += b.volume() * std::hypot(ax - bx, az - bz);
            shift_weight += b.volume();
        }
    }
    DepthError e;
    e.l1 = sums.area > 0.0 ? sums.abs_volume_error / sums.area : 0.0;
    e.linf = sums.linf;
    e.rel_l1 = sums.ref_volume > 0.0 ? sums.abs_volume_error / sums.ref_volume : 0.0;
    e.centroid_shift = shift_weight > 0.0 ? shift_weighted / shift_weight : 0.0;
    e.volume_ratio = sums.ref_volume > 0.0 ? run_volume / sums.ref_volume : 0.0;
    return e;
}

} // namespace snow::accuracy
