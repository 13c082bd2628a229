// The C API (<snow/snow.h>): each call catches every exception at the
// boundary, keeps its text for snow_last_error() and returns a status.
#include <snow/snow.h>

#include <snow/scene.hpp>

#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <vector>

struct snow_sim {
    std::unique_ptr<snow::Simulation> sim;
};

namespace {

thread_local std::string last_error;

snow_status fail(snow_status status, std::string text) {
    last_error = std::move(text);
    return status;
}

/// Runs `body` (which returns a status), turning exceptions into statuses.
template <typename Body>
snow_status guarded(const Body& body) {
    try {
        last_error.clear();
        return body();
    } catch (const snow::SimulationError& e) {
        return fail(std::string(e.field()).rfind("snapshot", 0) == 0 ? SNOW_ERROR_SNAPSHOT
                                                                     : SNOW_ERROR_ARGUMENT,
                    e.what());
    } catch (const std::bad_alloc&) {
        return fail(SNOW_ERROR_INTERNAL, "out of memory");
    } catch (const std::exception& e) {
        return fail(SNOW_ERROR_INTERNAL, e.what());
    }
}

/// The grid at `index` of Simulation::snow_grid (covers included), or none.
std::optional<snow::SnowGrid> surface_at(const snow_sim* s, std::size_t index) {
    if (index >= s->sim->snow_grid_count()) {
        return std::nullopt;
    }
    return s->sim->snow_grid(index);
}

#define SNOW_REQUIRE(cond, what)                                                                   \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            return fail(SNOW_ERROR_ARGUMENT, what);                                                \
        }                                                                                          \
    } while (false)

} // namespace

extern "C" {

const char* snow_last_error(void) {
    return last_error.c_str();
}

void snow_work_budget_default(snow_work_budget* out) {
    if (out == nullptr) {
        return;
    }
    const snow::WorkBudget b;
    *out = {b.snow_cells, b.surfaces,    b.collider_triangles, b.bodies,
            b.flakes,     b.field_cells, b.field_cell_sweeps,  b.occlusion_texels};
}

snow_status snow_sim_create_from_file(const char* path, snow_sim** out) {
    return snow_sim_create_from_file_within(path, nullptr, out);
}

snow_status snow_sim_create_from_file_within(const char* path, const snow_work_budget* budget,
                                             snow_sim** out) {
    return guarded([&] {
        SNOW_REQUIRE(out != nullptr, "snow_sim_create_from_file: out is null");
        *out = nullptr;
        SNOW_REQUIRE(path != nullptr, "snow_sim_create_from_file: path is null");
        snow::SceneOverrides o;
        if (budget != nullptr) {
            o.budget = {budget->snow_cells,
                        budget->surfaces,
                        budget->collider_triangles,
                        budget->bodies,
                        budget->flakes,
                        budget->field_cells,
                        budget->field_cell_sweeps,
                        budget->occlusion_texels};
        }
        snow::SceneLoadResult scene = snow::load_scene_file(path, o);
        if (!scene.sim) {
            return fail(SNOW_ERROR_SCENE, scene.error);
        }
        *out = new snow_sim{std::move(scene.sim)};
        return SNOW_OK;
    });
}

void snow_sim_destroy(snow_sim* sim) {
    delete sim;
}

snow_status snow_sim_step(snow_sim* sim, uint64_t ticks) {
    return guarded([&] {
        SNOW_REQUIRE(sim != nullptr, "snow_sim_step: sim is null");
        sim->sim->run(ticks);
        return SNOW_OK;
    });
}

snow_status snow_sim_tick_count(const snow_sim* sim, uint64_t* out) {
    SNOW_REQUIRE(sim != nullptr && out != nullptr, "snow_sim_tick_count: sim or out is null");
    *out = sim->sim->tick_count();
    return SNOW_OK;
}

snow_status snow_sim_state_hash(const snow_sim* sim, uint64_t* out) {
    return guarded([&] {
        SNOW_REQUIRE(sim != nullptr && out != nullptr, "snow_sim_state_hash: sim or out is null");
        *out = sim->sim->state_hash();
        return SNOW_OK;
    });
}

snow_status snow_sim_mass(const snow_sim* sim, snow_mass* out) {
    return guarded([&] {
        SNOW_REQUIRE(sim != nullptr && out != nullptr, "snow_sim_mass: sim or out is null");
        const snow::MassReport m = sim->sim->mass();
        *out = {m.spawned, m.airborne, m.settled, m.carried, m.removed};
        return SNOW_OK;
    });
}

snow_status snow_sim_surface_count(const snow_sim* sim, size_t* out) {
    SNOW_REQUIRE(sim != nullptr && out != nullptr, "snow_sim_surface_count: sim or out is null");
    *out = sim->sim->snow_grid_count();
    return SNOW_OK;
}

snow_status snow_sim_surface_grid(const snow_sim* sim, size_t index, snow_grid* out) {
    SNOW_REQUIRE(sim != nullptr && out != nullptr, "snow_sim_surface_grid: sim or out is null");
    const std::optional<snow::SnowGrid> s = surface_at(sim, index);
    SNOW_REQUIRE(s.has_value(), "snow_sim_surface_grid: index is past the last surface");
    *out = {s->nx, s->nz, s->x0, s->z0, s->cell};
    return SNOW_OK;
}

snow_status snow_sim_surface_depth(const snow_sim* sim, size_t index, float* out, size_t n) {
    SNOW_REQUIRE(sim != nullptr && out != nullptr, "snow_sim_surface_depth: sim or out is null");
    const std::optional<snow::SnowGrid> s = surface_at(sim, index);
    SNOW_REQUIRE(s.has_value(), "snow_sim_surface_depth: index is past the last surface");
    if (n < s->cell_count()) {
        return fail(SNOW_ERROR_BUFFER, "snow_sim_surface_depth: n is smaller than nx * nz (" +
                                           std::to_string(s->cell_count()) + ")");
    }
    for (std::size_t i = 0; i < s->cell_count(); ++i) {
        out[i] = s->depth(i);
    }
    return SNOW_OK;
}

snow_status snow_sim_flake_positions(const snow_sim* sim, float* xyz, size_t max, size_t* count) {
    SNOW_REQUIRE(sim != nullptr && count != nullptr,
                 "snow_sim_flake_positions: sim or count is null");
    SNOW_REQUIRE(xyz != nullptr || max == 0, "snow_sim_flake_positions: xyz is null");
    const snow::FlakesView f = sim->sim->flakes();
    std::size_t k = 0;
    for (std::size_t i = 0; i < f.slots() && k < max; ++i) {
        if (f.is_alive(i)) {
            xyz[3 * k] = f.x[i];
            xyz[3 * k + 1] = f.y[i];
            xyz[3 * k + 2] = f.z[i];
            ++k;
        }
    }
    *count = f.alive;
    return SNOW_OK;
}

snow_status snow_sim_save(const snow_sim* sim, void* buf, size_t cap, size_t* needed) {
    return guarded([&] {
        SNOW_REQUIRE(sim != nullptr && needed != nullptr, "snow_sim_save: sim or needed is null");
        const std::vector<std::byte> bytes = sim->sim->save_bytes();
        *needed = bytes.size();
        if (cap < bytes.size()) {
            return fail(SNOW_ERROR_BUFFER, "snow_sim_save: cap is smaller than the snapshot (" +
                                               std::to_string(bytes.size()) + " bytes)");
        }
        SNOW_REQUIRE(buf != nullptr, "snow_sim_save: buf is null");
        std::memcpy(buf, bytes.data(), bytes.size());
        return SNOW_OK;
    });
}

snow_status snow_sim_load(snow_sim* sim, const void* buf, size_t size) {
    return guarded([&] {
        SNOW_REQUIRE(sim != nullptr, "snow_sim_load: sim is null");
        SNOW_REQUIRE(buf != nullptr || size == 0, "snow_sim_load: buf is null");
        sim->sim->load_bytes({static_cast<const std::byte*>(buf), size});
        return SNOW_OK;
    });
}

} // extern "C"
