/// @file field_rules.hpp
/// @brief The values a settings field accepts, and the table type that lists
/// the fields of a settings struct: per field its name (as scenes and error
/// messages spell it), its member and its Range. validate() runs a struct's
/// table with check_fields(); the scene loader reads the same fields from
/// JSON by walking the same table (internal to snow::sim).
#pragma once

#include "ecs/error.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <variant>

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

inline constexpr double unbounded = std::numeric_limits<double>::infinity();

/// The values a number accepts (each component of a vector). A value that is
/// not finite is never accepted.
struct Range {
    double min = -unbounded;
    double max = unbounded;
    bool min_exclusive = false; ///< true: > min; false: >= min
    bool max_exclusive = false; ///< true: < max; false: <= max
};
inline constexpr Range positive{0.0, unbounded, true};
inline constexpr Range non_negative{0.0};
[[nodiscard]] constexpr Range between(double min, double max) {
    return {min, max};
}
[[nodiscard]] constexpr Range at_least(double min) {
    return {min, unbounded};
}
[[nodiscard]] constexpr Range up_to(double max) {
    return {-unbounded, max};
}
[[nodiscard]] constexpr Range positive_up_to(double max) {
    return {0.0, max, true};
}
/// [min, max): a share that cannot be whole, such as a fence's porosity.
[[nodiscard]] constexpr Range from_below(double min, double max) {
    return {min, max, false, true};
}

/// What is wrong with `v` under `r` ("must be > 0 (got -1)": the bound it
/// breaks), or empty when `r` accepts it.
[[nodiscard]] std::string range_problem(const Range& r, double v);

/// The members a settings field can be.
template <typename T>
using SettingMember =
    std::variant<float T::*, std::uint32_t T::*, std::uint64_t T::*, bool T::*, glm::vec3 T::*>;

/// One row of a settings struct's table.
template <typename T>
struct FieldRule {
    std::string_view name; ///< "rate", "min.x": the field's name below its struct's
    SettingMember<T> member;
    Range range = {}; ///< for numbers (every component of a vector); any finite value if omitted
};

// One field's value against its range, named "prefix.name" when it fails.
// A float is compared with the range's bounds as floats (the float a user
// writes for a bound is accepted); a vector names the failing component
// ("prefix.name.x").
void check_field(Invalid& err, std::string_view prefix, std::string_view name, const Range& r,
                 float v);
void check_field(Invalid& err, std::string_view prefix, std::string_view name, const Range& r,
                 std::uint64_t v);
void check_field(Invalid& err, std::string_view prefix, std::string_view name, const Range& r,
                 const glm::vec3& v);
inline void check_field(Invalid& err, std::string_view prefix, std::string_view name,
                        const Range& r, std::uint32_t v) {
    check_field(err, prefix, name, r, std::uint64_t{v});
}
inline void check_field(Invalid&, std::string_view, std::string_view, const Range&, bool) {}

/// Records in `err` (when it holds no problem yet) the first field of `value`
/// that its row's range rejects, named "prefix.name".
template <typename T, std::size_t N>
void check_fields(Invalid& err, std::string_view prefix, const FieldRule<T> (&table)[N],
                  const T& value) {
    for (const FieldRule<T>& f : table) {
        std::visit([&](auto member) { check_field(err, prefix, f.name, f.range, value.*member); },
                   f.member);
    }
}

/// The first field of `value` that its row's range rejects, or no problem.
template <typename T, std::size_t N>
[[nodiscard]] Invalid check_fields(std::string_view prefix, const FieldRule<T> (&table)[N],
                                   const T& value) {
    Invalid err;
    check_fields(err, prefix, table, value);
    return err;
}

} // namespace snow

/// Checks of values no table holds (derived sizes, handles, arguments); each
/// records its problem only while `err` holds none.
namespace snow::check {

/// Records "field must be <rule> (got v)".
void fail(Invalid& err, std::string_view field, const std::string& rule, double v);
/// Records the problem of `v` under `r`.
void number(Invalid& err, std::string_view field, const Range& r, double v);
/// Each component finite ("field.x", ...).
void finite3(Invalid& err, std::string_view field, const glm::vec3& v);
/// Each point finite ("field[i].x", ...; the name is made only for the point at fault).
void finite_each(Invalid& err, std::string_view field, std::span<const glm::vec3> points);
/// prefix.hi >= prefix.lo (> when `strict`); skipped while either is not finite.
void ordered(Invalid& err, std::string_view prefix, std::string_view lo_name, double lo,
             std::string_view hi_name, double hi, bool strict = false);

} // namespace snow::check
