/// @file share_work.hpp
/// @brief Test support: makes a simulation hand its flake chunks to its job
/// pool at any size. for_chunks keeps passes below Jobs::min_items on the
/// calling thread, so without this a small test scene on 2 threads would
/// never run a chunk on the second one.
#pragma once

#include "systems/api/simulation_internals.hpp"
#include "systems/core/jobs.hpp"

namespace snow::test {

inline void share_work_at_any_size(Simulation& sim) {
    InternalAccess::world(sim).resource<Jobs>().min_items = 0;
}

} // namespace snow::test
