/// @file cpu_clock.hpp
/// @brief CPU time of the calling thread: on a shared, loaded machine it
/// leaves out the time other processes hold the core (wall time does not).
#pragma once

#include <ctime>

namespace snow::accuracy {

/// Seconds of CPU time this thread has used.
[[nodiscard]] inline double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1.0e-9 * static_cast<double>(t.tv_nsec);
}

} // namespace snow::accuracy
