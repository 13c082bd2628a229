// The checks behind the settings tables. One wording for every range problem,
// so the facade and the scene loader report a field alike; names are joined
// only when a check fails (valid values cost no allocation).
#include "systems/core/field_rules.hpp"

#include <cmath>

namespace snow {

namespace {

/// A bound as messages print it: whole numbers in full (16777216, not 1.67772e+07).
std::string bound_text(double b) {
    if (std::abs(b) < 9.0e15 && b == std::floor(b)) {
        return std::to_string(static_cast<std::int64_t>(b));
    }
    return number_text(b);
}

/// "prefix.name", or `name` alone under no prefix.
std::string joined(std::string_view prefix, std::string_view name) {
    std::string s(prefix);
    if (!s.empty()) {
        s += '.';
    }
    s += name;
    return s;
}

/// Records `problem` of field "prefix.name" while `err` holds none; the
/// name is joined only then.
void record(Invalid& err, std::string_view prefix, std::string_view name, std::string problem) {
    if (err.empty() && !problem.empty()) {
        err = {joined(prefix, name), std::move(problem)};
    }
}

/// range_problem() compared in N: a float against the bounds rounded to floats.
template <typename N>
std::string problem_in(const Range& r, N v) {
    const N lo = static_cast<N>(r.min);
    const N hi = static_cast<N>(r.max);
    std::string rule;
    if (!std::isfinite(v)) {
        rule = "finite";
    } else if (r.min_exclusive ? !(v > lo) : v < lo) {
        rule = r.min_exclusive ? "> " : ">= ";
        rule += bound_text(lo);
    } else if (r.max_exclusive ? !(v < hi) : v > hi) {
        rule = r.max_exclusive ? "< " : "<= ";
        rule += bound_text(hi);
    } else {
        return {};
    }
    return "must be " + rule + " (got " + number_text(v) + ")";
}

} // namespace

std::string range_problem(const Range& r, double v) {
    return problem_in(r, v);
}

void check_field(Invalid& err, std::string_view prefix, std::string_view name, const Range& r,
                 float v) {
    if (err.empty()) {
        record(err, prefix, name, problem_in(r, v));
    }
}

void check_field(Invalid& err, std::string_view prefix, std::string_view name, const Range& r,
                 std::uint64_t v) {
    if (err.empty()) {
        record(err, prefix, name, range_problem(r, static_cast<double>(v)));
    }
}

void check_field(Invalid& err, std::string_view prefix, std::string_view name, const Range& r,
                 const glm::vec3& v) {
    static constexpr const char* axes[] = {".x", ".y", ".z"};
    for (int i = 0; i < 3 && err.empty(); ++i) {
        if (std::string problem = problem_in(r, v[i]); !problem.empty()) {
            err = {joined(prefix, name) + axes[i], std::move(problem)};
        }
    }
}

} // namespace snow

namespace snow::check {

void fail(Invalid& err, std::string_view field, const std::string& rule, double v) {
    record(err, "", field, "must be " + rule + " (got " + number_text(v) + ")");
}

void number(Invalid& err, std::string_view field, const Range& r, double v) {
    if (err.empty()) {
        record(err, "", field, range_problem(r, v));
    }
}

void finite3(Invalid& err, std::string_view field, const glm::vec3& v) {
    check_field(err, "", field, {}, v);
}

void finite_each(Invalid& err, std::string_view field, std::span<const glm::vec3> points) {
    for (std::size_t i = 0; i < points.size() && err.empty(); ++i) {
        const glm::vec3& v = points[i];
        if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) {
            std::string name(field);
            name.append("[").append(std::to_string(i)).append("]");
            finite3(err, name, v);
        }
    }
}

void ordered(Invalid& err, std::string_view prefix, std::string_view lo_name, double lo,
             std::string_view hi_name, double hi, bool strict) {
    if (err.empty() && std::isfinite(lo) && std::isfinite(hi) && (strict ? !(hi > lo) : hi < lo)) {
        std::string rule = strict ? "> " : ">= ";
        rule += joined(prefix, lo_name);
        rule += " (" + number_text(lo) + ")";
        fail(err, joined(prefix, hi_name), rule, hi);
    }
}

} // namespace snow::check
