/// @file validation.hpp
/// @brief Shared checks for user-supplied numbers; messages name the field.
#pragma once

#include <glm/vec3.hpp>

#include <cmath>
#include <sstream>
#include <string>

namespace snow::check {

/// Appends "field must be ... (got v)" to `err` when it is still empty.
inline void fail(std::string& err, const std::string& field, const std::string& rule, double v) {
    if (err.empty()) {
        std::ostringstream os;
        os << field << " must be " << rule << " (got " << v << ")";
        err = os.str();
    }
}
inline void finite(std::string& err, const std::string& field, double v) {
    if (!std::isfinite(v)) {
        fail(err, field, "finite", v);
    }
}
inline void positive(std::string& err, const std::string& field, double v) {
    finite(err, field, v);
    if (std::isfinite(v) && !(v > 0.0)) {
        fail(err, field, "> 0", v);
    }
}
inline void non_negative(std::string& err, const std::string& field, double v) {
    finite(err, field, v);
    if (std::isfinite(v) && v < 0.0) {
        fail(err, field, ">= 0", v);
    }
}
inline void at_most(std::string& err, const std::string& field, double v, double max) {
    if (std::isfinite(v) && v > max) {
        fail(err, field, "<= " + std::to_string(max), v);
    }
}
inline void finite3(std::string& err, const std::string& field, const glm::vec3& v) {
    finite(err, field + ".x", v.x);
    finite(err, field + ".y", v.y);
    finite(err, field + ".z", v.z);
}
/// lo <= hi, both finite and within their own rules already checked.
inline void ordered(std::string& err, const std::string& lo_field, double lo,
                    const std::string& hi_field, double hi) {
    if (std::isfinite(lo) && std::isfinite(hi) && lo > hi) {
        fail(err, hi_field, ">= " + lo_field + " (" + std::to_string(lo) + ")", hi);
    }
}

} // namespace snow::check
