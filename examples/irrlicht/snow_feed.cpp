#include "snow_feed.hpp"

#include <snow/scene.hpp>

#include <algorithm>
#include <optional>

namespace {

Vec3 vec(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

/// The ground a host draws snow on: the largest cover or surface that lies
/// on no solid (snow_game's readout picks the same one); none when none.
std::optional<std::size_t> find_ground(const snow::Simulation& sim) {
    std::optional<std::size_t> best;
    std::size_t best_cells = 0;
    for (std::size_t i = 0; i < sim.snow_grid_count(); ++i) {
        const snow::SnowGrid g = sim.snow_grid(i);
        const bool ground = !g.cover.is_null() || g.owner.is_null();
        if (ground && g.cell_count() > best_cells) {
            best = i;
            best_cells = g.cell_count();
        }
    }
    return best;
}

} // namespace

struct SnowFeed::State {
    snow::SceneLoadResult scene;
    std::size_t ground; ///< its snow_grid() index (the scene never removes one)
    snow::FixedStep step;

    [[nodiscard]] snow::Simulation& sim() const { return *scene.sim; }
    [[nodiscard]] snow::SnowGrid surface() const { return sim().snow_grid(ground); }
};

std::unique_ptr<SnowFeed> SnowFeed::load(const std::string& path, std::string& error) {
    snow::SceneLoadResult scene = snow::load_scene_file(path);
    if (!scene.sim) {
        error = scene.error;
        return nullptr;
    }
    const std::optional<std::size_t> ground = find_ground(*scene.sim);
    if (!ground) {
        error = path + ": no snow cover and no surface on the ground";
        return nullptr;
    }
    const double dt = scene.sim->config().dt;
    return std::unique_ptr<SnowFeed>(new SnowFeed(
        std::make_unique<State>(State{std::move(scene), *ground, snow::FixedStep(dt)})));
}

SnowFeed::SnowFeed(std::unique_ptr<State> state) : state_(std::move(state)) {}
SnowFeed::~SnowFeed() = default;

std::uint32_t SnowFeed::advance(std::uint32_t elapsed_ms) {
    const std::uint32_t ticks = state_->step.advance(elapsed_ms / 1000.0);
    state_->sim().run(ticks);
    return ticks;
}

std::string SnowFeed::name() const {
    return state_->scene.name;
}

View SnowFeed::view() const {
    const snow::SceneVisuals& v = state_->scene.visuals;
    return {vec(v.camera.position), vec(v.camera.target), v.camera.fov_y_deg,
            v.camera.near_plane,    v.camera.far_plane,   vec(v.environment.sky)};
}

Vec3 SnowFeed::bounds_min() const {
    return vec(state_->sim().config().bounds.min);
}
Vec3 SnowFeed::bounds_max() const {
    return vec(state_->sim().config().bounds.max);
}

void SnowFeed::flakes(std::vector<Vec3>& out) const {
    const snow::FlakesView flakes = state_->sim().flakes();
    out.clear();
    for (std::size_t slot = 0; slot < flakes.slots(); ++slot) {
        if (flakes.is_alive(slot)) {
            out.push_back({flakes.x[slot], flakes.y[slot], flakes.z[slot]});
        }
    }
}

std::uint32_t SnowFeed::ground_nx() const {
    return state_->surface().nx;
}
std::uint32_t SnowFeed::ground_nz() const {
    return state_->surface().nz;
}

void SnowFeed::ground(std::vector<GroundPoint>& out) const {
    const snow::SnowGrid s = state_->surface();
    out.clear();
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const std::size_t i = s.index(ix, iz);
            out.push_back({s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell,
                           s.z0 + (static_cast<float>(iz) + 0.5f) * s.cell,
                           s.base_y(i) + s.depth(i), s.depth(i), s.has_ground(i)});
        }
    }
}

std::uint64_t SnowFeed::ground_base_version() const {
    return state_->surface().base_version;
}

float SnowFeed::deepest_snow() const {
    const snow::SnowGrid s = state_->surface();
    float deepest = 0.0f;
    for (std::size_t i = 0; i < s.cell_count(); ++i) {
        deepest = std::max(deepest, s.depth(i));
    }
    return deepest;
}

std::uint64_t SnowFeed::ticks() const {
    return state_->sim().tick_count();
}
std::uint64_t SnowFeed::state_hash() const {
    return state_->sim().state_hash();
}
