/// @file simulation_error.hpp
/// @brief The error of the Simulation facade: an invalid argument, named by
/// its field (e.g. `emitter.rate must be >= 0 (got -1)`). A call that throws
/// leaves the simulation exactly as it was.
#pragma once

#include "ecs/error.hpp"

namespace snow {

class SimulationError : public Error {
  public:
    using Error::Error;
};

} // namespace snow
