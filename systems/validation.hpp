/// @file validation.hpp
/// @brief validate() for every settings struct of the facade, and the checks
/// they share; each names the field at fault (internal to snow::sim, used by
/// the facade and the scene loader).
#pragma once

#include "systems/body.hpp"
#include "systems/emitter.hpp"
#include "systems/flake_pool.hpp"
#include "systems/fog.hpp"
#include "systems/geometry.hpp"
#include "systems/sim_config.hpp"
#include "systems/simulation_error.hpp"
#include "systems/spectral_snow.hpp"
#include "systems/wind.hpp"
#include "systems/wind_field.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <sstream>
#include <string>

namespace snow {

/// The first bad value found in user input: which field, and what is wrong.
struct Invalid {
    std::string field;   ///< e.g. "emitter.rate"; empty while every value is fine
    std::string problem; ///< e.g. "must be >= 0 (got -1)"
    [[nodiscard]] bool empty() const { return field.empty(); }
    /// "field problem", as error messages print it.
    [[nodiscard]] std::string text() const { return field + " " + problem; }
};

/// Throws SimulationError(field, problem) when `v` holds a problem.
inline void throw_if(const Invalid& v) {
    if (!v.empty()) {
        throw SimulationError(v.field, v.problem);
    }
}

[[nodiscard]] Invalid validate(const SimConfig& c);
[[nodiscard]] Invalid validate(const Emitter& e);
/// A box collider's extent (fields "box.min", "box.max").
[[nodiscard]] Invalid validate(const Aabb& box);
[[nodiscard]] Invalid validate(const FlakeSpec& f);
[[nodiscard]] Invalid validate(const Wind& w);
[[nodiscard]] Invalid validate(const Fog& f);
[[nodiscard]] Invalid validate(const SpectralSnow& s);
/// A scripted path (fields "motion.waypoints", "motion.speed").
[[nodiscard]] Invalid validate(const BodyMotion& motion);
/// A body's shape and size, and its motion when it has waypoints (fields "body.*").
[[nodiscard]] Invalid validate(const BodyDef& def);
/// A wind field's grid and solver settings (fields "wind.field.*").
[[nodiscard]] Invalid validate(const WindFieldDef& d);
/// Snow transport by the field's wind (fields "wind.field.transport.*").
[[nodiscard]] Invalid validate(const WindTransportDef& t);

} // namespace snow

namespace snow::check {

/// Records "field must be ... (got v)" in `err` when it holds no problem yet.
inline void fail(Invalid& err, const std::string& field, const std::string& rule, double v) {
    if (err.empty()) {
        std::ostringstream os;
        os << "must be " << rule << " (got " << v << ")";
        err = {field, os.str()};
    }
}
inline void finite(Invalid& err, const std::string& field, double v) {
    if (!std::isfinite(v)) {
        fail(err, field, "finite", v);
    }
}
inline void positive(Invalid& err, const std::string& field, double v) {
    finite(err, field, v);
    if (std::isfinite(v) && !(v > 0.0)) {
        fail(err, field, "> 0", v);
    }
}
inline void non_negative(Invalid& err, const std::string& field, double v) {
    finite(err, field, v);
    if (std::isfinite(v) && v < 0.0) {
        fail(err, field, ">= 0", v);
    }
}
inline void at_most(Invalid& err, const std::string& field, double v, double max) {
    if (std::isfinite(v) && v > max) {
        fail(err, field, "<= " + std::to_string(max), v);
    }
}
inline void finite3(Invalid& err, const std::string& field, const glm::vec3& v) {
    finite(err, field + ".x", v.x);
    finite(err, field + ".y", v.y);
    finite(err, field + ".z", v.z);
}
/// lo <= hi, both finite and within their own rules already checked.
inline void ordered(Invalid& err, const std::string& lo_field, double lo,
                    const std::string& hi_field, double hi) {
    if (std::isfinite(lo) && std::isfinite(hi) && lo > hi) {
        fail(err, hi_field, ">= " + lo_field + " (" + std::to_string(lo) + ")", hi);
    }
}

} // namespace snow::check
