/* A C host of snow (<snow/snow.h>, target snow::c): loads a scene, steps it,
 * checks the mass books, reads the snow depth and the flakes, and saves and
 * restores a snapshot: the restored run must reach the same state hash as
 * the uninterrupted one. Exits 0 when every check holds, 1 otherwise, 2 for
 * bad arguments or a scene that cannot be loaded. */
#include <snow/snow.h>

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failed = 0;

static void check(int ok, const char* what) {
    printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
    failed |= !ok;
}

static int balanced(const snow_sim* sim) {
    snow_mass m;
    if (snow_sim_mass(sim, &m) != SNOW_OK) {
        return 0;
    }
    printf("      mass: spawned %" PRIu64 " = airborne %" PRIu64 " + settled %" PRIu64
           " + carried %" PRIu64 " + removed %" PRIu64 "\n",
           m.spawned, m.airborne, m.settled, m.carried, m.removed);
    return m.spawned == m.airborne + m.settled + m.carried + m.removed && m.settled > 0;
}

int main(int argc, char** argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s SCENE.gltf\n", argv[0]);
        return 2;
    }
    snow_sim* sim = NULL;
    if (snow_sim_create_from_file(argv[1], &sim) != SNOW_OK) {
        fprintf(stderr, "snow_c_host: %s\n", snow_last_error());
        return 2;
    }
    snow_work_budget tight;
    snow_work_budget_default(&tight);
    tight.flakes = 1; /* the scene's pool is larger */
    snow_sim* refused = NULL;
    check(snow_sim_create_from_file_within(argv[1], &tight, &refused) == SNOW_ERROR_SCENE &&
              refused == NULL && strstr(snow_last_error(), "budget.flakes") != NULL,
          "a scene past the host's work budget is refused, naming the budget");
    check(snow_sim_step(sim, 240) == SNOW_OK, "240 ticks");
    check(balanced(sim), "the ledger balances and snow has settled");

    size_t surfaces = 0;
    snow_grid grid;
    check(snow_sim_surface_count(sim, &surfaces) == SNOW_OK && surfaces > 0, "surfaces listed");
    check(snow_sim_surface_grid(sim, 0, &grid) == SNOW_OK, "the first surface's grid");
    float* depth = malloc(sizeof(float) * (size_t)grid.nx * grid.nz);
    check(depth != NULL &&
              snow_sim_surface_depth(sim, 0, depth, (size_t)grid.nx * grid.nz) == SNOW_OK,
          "its depth grid");
    check(snow_sim_surface_depth(sim, 0, depth, 1) == SNOW_ERROR_BUFFER || grid.nx * grid.nz <= 1,
          "a short depth buffer is refused");
    check(snow_sim_surface_grid(sim, surfaces, &grid) == SNOW_ERROR_ARGUMENT &&
              strstr(snow_last_error(), "index") != NULL,
          "an index past the last surface is refused, naming the index");
    free(depth);

    size_t falling = 0;
    float first[3 * 16];
    check(snow_sim_flake_positions(sim, first, 16, &falling) == SNOW_OK && falling > 0,
          "flake positions");

    size_t size = 0;
    check(snow_sim_save(sim, NULL, 0, &size) == SNOW_ERROR_BUFFER && size > 0, "snapshot size");
    void* saved = malloc(size);
    check(saved != NULL && snow_sim_save(sim, saved, size, &size) == SNOW_OK, "snapshot saved");
    uint64_t ahead = 0, replayed = 0;
    snow_sim_step(sim, 120);
    snow_sim_state_hash(sim, &ahead);
    check(snow_sim_load(sim, saved, size / 2) == SNOW_ERROR_SNAPSHOT &&
              strstr(snow_last_error(), "cut short") != NULL,
          "half a snapshot is refused as cut short");
    check(snow_sim_load(sim, saved, size) == SNOW_OK, "snapshot loaded");
    snow_sim_step(sim, 120);
    snow_sim_state_hash(sim, &replayed);
    printf("      state hash after 360 ticks: %016" PRIx64 ", after the round trip: %016" PRIx64
           "\n",
           ahead, replayed);
    check(ahead == replayed, "the restored run reaches the same state hash");
    check(balanced(sim), "the ledger balances after the round trip");
    free(saved);
    snow_sim_destroy(sim);
    return failed ? 1 : 0;
}
