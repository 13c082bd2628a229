/// @file validation.hpp
/// @brief Every settings struct's field table and validate(), gathered for
/// the facade and the scene loader. Each lives beside its struct (the table in
/// its header, validate() in its source) and names the field at fault.
#pragma once

#include "systems/bodies/body.hpp"
#include "systems/core/field_rules.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/flakes/emitter.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/geometry/geometry.hpp"
#include "systems/sky/occlusion.hpp"
#include "systems/snowpack/snow_cover.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/wind.hpp"
#include "systems/wind/wind_field.hpp"
#include "systems/wind/wind_transport.hpp"
