/// @file snow.hpp
/// @brief The simulation API (target snow::sim, no GL): create a Simulation
/// from code (or from a glTF file with <snow/scene.hpp>), change it only
/// through its validated calls, step it at a fixed dt (FixedStep turns host
/// frames into ticks), read flakes, surfaces and covers, moving bodies, the
/// state hash and the mass report. Everything it throws is a snow::Error.
/// See docs/embedding.md and docs/cover_and_bodies.md.
#pragma once

#include "systems/api/fixed_step.hpp"
#include "systems/api/simulation.hpp"
#include "systems/core/units.hpp"

#include <snow/defs.hpp>
#include <snow/task_system.hpp>
