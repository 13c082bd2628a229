/* @file snow.h
 * @brief The C API of snow (C11; target snow::c): a simulation loaded from a
 * glTF scene file behind an opaque handle, stepped at its fixed tick, read
 * into caller-owned buffers, saved and loaded as bytes. Every call returns a
 * snow_status; on failure snow_last_error() gives the text (the field and
 * what is wrong) and the simulation is unchanged. No exception crosses this
 * API. Self-contained: includes only <stddef.h> and <stdint.h>.
 * See docs/embedding.md "The C API". */
#ifndef SNOW_SNOW_H
#define SNOW_SNOW_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* An opaque simulation handle. */
typedef struct snow_sim snow_sim;

typedef enum snow_status {
    SNOW_OK = 0,
    SNOW_ERROR_ARGUMENT = 1, /* a null handle or pointer, an index past the end */
    SNOW_ERROR_SCENE = 2,    /* the scene file cannot be read or is not a snow scene */
    SNOW_ERROR_SNAPSHOT = 3, /* bytes that are not a snapshot of this scene */
    SNOW_ERROR_BUFFER = 4,   /* the caller's buffer is too small (nothing written) */
    SNOW_ERROR_INTERNAL = 5  /* anything else (out of memory, ...) */
} snow_status;

/* The mass books in whole units: spawned == airborne + settled + carried + removed. */
typedef struct snow_mass {
    uint64_t spawned;
    uint64_t airborne; /* in falling flakes */
    uint64_t settled;  /* on surfaces and covers */
    uint64_t carried;  /* in snowballs */
    uint64_t removed;  /* left the bounds, melted into spheres, landed on bare geometry, ... */
} snow_mass;

/* A surface's (or cover's) depth grid: nx × nz cells of `cell` metres from
 * (x0, z0), row-major with x fastest. */
typedef struct snow_grid {
    uint32_t nx, nz;
    float x0, z0, cell;
} snow_grid;

/* The text of the last failed call on this thread ("" when none failed). */
const char* snow_last_error(void);

/* The most work a scene file may declare (docs/scenes.md, "Work budget"):
 * a file past any of these is refused with SNOW_ERROR_SCENE, naming the
 * declaration, before anything is allocated. */
typedef struct snow_work_budget {
    uint64_t snow_cells;         /* the surfaces' and the cover's cells together */
    uint64_t surfaces;           /* snow surfaces */
    uint64_t collider_triangles; /* triangles of the mesh colliders */
    uint64_t bodies;             /* moving bodies */
    uint64_t flakes;             /* the flake pool (max_flakes) */
    uint64_t field_cells;        /* the wind field's cells */
    uint64_t field_cell_sweeps;  /* field cells times pressure_iterations */
    uint64_t occlusion_texels;   /* the sky map's resolution squared */
} snow_work_budget;

/* The default budget: every shipped scene fits several times over. */
void snow_work_budget_default(snow_work_budget* out);

/* Loads a .gltf or .glb scene file into a new simulation (*out); *out is null on failure. */
snow_status snow_sim_create_from_file(const char* path, snow_sim** out);
/* The same within `budget` (null: the default budget). */
snow_status snow_sim_create_from_file_within(const char* path, const snow_work_budget* budget,
                                             snow_sim** out);
/* Frees a simulation (null is fine). */
void snow_sim_destroy(snow_sim* sim);

/* Advances `ticks` fixed ticks. */
snow_status snow_sim_step(snow_sim* sim, uint64_t ticks);
/* Ticks completed so far. */
snow_status snow_sim_tick_count(const snow_sim* sim, uint64_t* out);
/* 64-bit hash of the whole simulation state (equal states, equal hashes). */
snow_status snow_sim_state_hash(const snow_sim* sim, uint64_t* out);
/* The mass books. */
snow_status snow_sim_mass(const snow_sim* sim, snow_mass* out);

/* Surfaces and covers, in a fixed order. */
snow_status snow_sim_surface_count(const snow_sim* sim, size_t* out);
/* The grid of surface `index`. */
snow_status snow_sim_surface_grid(const snow_sim* sim, size_t index, snow_grid* out);
/* Snow depth (m) of every cell of surface `index` into out[0 .. nx·nz); n must be at least nx·nz.
 */
snow_status snow_sim_surface_depth(const snow_sim* sim, size_t index, float* out, size_t n);

/* Writes x, y, z of up to `max` falling flakes into xyz (3·max floats) and
 * sets *count to how many are falling (which may be more than max). */
snow_status snow_sim_flake_positions(const snow_sim* sim, float* xyz, size_t max, size_t* count);

/* Writes the simulation's snapshot into buf. *needed is set to its size;
 * when cap is smaller, nothing is written and SNOW_ERROR_BUFFER is returned
 * (buf may then be null: a call with cap 0 asks for the size). */
snow_status snow_sim_save(const snow_sim* sim, void* buf, size_t cap, size_t* needed);
/* Restores a snapshot of the same scene (from this process or another). */
snow_status snow_sim_load(snow_sim* sim, const void* buf, size_t size);

#ifdef __cplusplus
}
#endif

#endif /* SNOW_SNOW_H */
