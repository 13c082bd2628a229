// The value readers behind the field tables. The JSON is nlohmann's (the one
// parse of the file), so integers keep all 64 bits and types are exactly the
// file's.
#include "game/scene/scene_fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

namespace {

/// "must be > 0", "must be in [0, 1]", ... for a range; empty when unbounded.
std::string range_rule(const Range& r) {
    const bool has_min = std::isfinite(r.min), has_max = std::isfinite(r.max);
    if (has_min && has_max) {
        return std::string(r.min_exclusive ? "in (" : "in [") + number_text(r.min) + ", " +
               number_text(r.max) + (r.max_exclusive ? ")" : "]");
    }
    if (has_min) {
        return (r.min_exclusive ? "> " : ">= ") + number_text(r.min);
    }
    return has_max ? (r.max_exclusive ? "< " : "<= ") + number_text(r.max) : "";
}

bool in_range(double v, const Range& r) {
    return (r.min_exclusive ? v > r.min : v >= r.min) && (r.max_exclusive ? v < r.max : v <= r.max);
}

double finite_number(const Json& j, const std::string& field, const Range& range, double limit) {
    if (!j.is_number()) {
        scene_fail(field, "must be a number (got " + json_type_name(j) + ")");
    }
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::abs(v) > limit) {
        scene_fail(field,
                   std::string("must be a finite number") +
                       (limit < std::numeric_limits<double>::max() ? " within float range" : "") +
                       " (got " + number_text(v) + ")");
    }
    if (!in_range(v, range)) {
        scene_fail(field, "must be " + range_rule(range) + " (got " + number_text(v) + ")");
    }
    return v;
}

/// An integer in the range, within [0, max].
std::uint64_t unsigned_integer(const Json& j, const std::string& field, const Range& range,
                               std::uint64_t max) {
    const std::uint64_t lo =
        range.min <= 0.0 ? 0 : static_cast<std::uint64_t>(std::ceil(range.min));
    const std::uint64_t hi =
        range.max >= static_cast<double>(max) ? max : static_cast<std::uint64_t>(range.max);
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "[" + std::string&&.
    std::string rule = "in [";
    rule += std::to_string(lo);
    rule += ", ";
    rule += std::to_string(hi);
    rule += "]";
    if (j.is_number_unsigned()) {
        const auto v = j.get<std::uint64_t>();
        if (v < lo || v > hi) {
            scene_fail(field, "must be " + rule + " (got " + std::to_string(v) + ")");
        }
        return v;
    }
    if (j.is_number_integer()) { // negative (non-negative ones parse as unsigned)
        scene_fail(field,
                   "must be " + rule + " (got " + std::to_string(j.get<std::int64_t>()) + ")");
    }
    if (j.is_number()) {
        scene_fail(field, "must be an integer (got " + number_text(j.get<double>()) + ")");
    }
    scene_fail(field, "must be an integer (got " + json_type_name(j) + ")");
}

/// Every element of an array read by the element type's read_value().
template <typename T>
void read_elements(const Json& j, const std::string& field, const Range& range,
                   std::vector<T>& out) {
    if (!j.is_array()) {
        scene_fail(field, "must be an array (got " + json_type_name(j) + ")");
    }
    out.resize(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        T element{};
        read_value(j[i], field + "[" + std::to_string(i) + "]", range, element);
        out[i] = std::move(element);
    }
}

} // namespace

std::string json_type_name(const Json& j) {
    switch (j.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::object:
        return "object";
    case Json::value_t::array:
        return "array";
    case Json::value_t::string:
        return "string";
    case Json::value_t::boolean:
        return "boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
        return "integer";
    case Json::value_t::number_float:
        return "number";
    default:
        return "unsupported value";
    }
}

void read_value(const Json& j, const std::string& field, const Range& range, float& out) {
    out = static_cast<float>(
        finite_number(j, field, range, static_cast<double>(std::numeric_limits<float>::max())));
}

void read_value(const Json& j, const std::string& field, const Range& range, double& out) {
    out = finite_number(j, field, range, std::numeric_limits<double>::max());
}

void read_value(const Json& j, const std::string& field, const Range&, bool& out) {
    if (!j.is_boolean()) {
        scene_fail(field, "must be true or false (got " + json_type_name(j) + ")");
    }
    out = j.get<bool>();
}

void read_value(const Json& j, const std::string& field, const Range& range, std::uint32_t& out) {
    out = static_cast<std::uint32_t>(
        unsigned_integer(j, field, range, std::numeric_limits<std::uint32_t>::max()));
}

void read_value(const Json& j, const std::string& field, const Range& range, std::uint64_t& out) {
    out = unsigned_integer(j, field, range, std::numeric_limits<std::uint64_t>::max());
}

void read_value(const Json& j, const std::string& field, const Range& range,
                std::optional<std::uint64_t>& out) {
    out = unsigned_integer(j, field, range, std::numeric_limits<std::uint64_t>::max());
}

void read_value(const Json& j, const std::string& field, const Range&, std::string& out) {
    if (!j.is_string()) {
        scene_fail(field, "must be a string (got " + json_type_name(j) + ")");
    }
    out = j.get<std::string>();
}

void read_value(const Json& j, const std::string& field, const Range& range,
                std::optional<std::string>& out) {
    read_value(j, field, range, out.emplace());
}

void read_value(const Json& j, const std::string& field, const Range& range, glm::vec3& out) {
    if (!j.is_array() || j.size() != 3) {
        scene_fail(field,
                   "must be an array of 3 numbers (got " +
                       (j.is_array() ? "array of " + std::to_string(j.size()) : json_type_name(j)) +
                       ")");
    }
    for (int i = 0; i < 3; ++i) {
        read_value(j[static_cast<std::size_t>(i)], field + "[" + std::to_string(i) + "]", range,
                   out[i]);
    }
}

void read_value(const Json& j, const std::string& field, const Range& range,
                std::vector<double>& out) {
    read_elements(j, field, range, out);
}

void read_value(const Json& j, const std::string& field, const Range& range,
                std::vector<std::uint64_t>& out) {
    read_elements(j, field, range, out);
}

void read_value(const Json& j, const std::string& field, const Range& range,
                std::vector<std::string>& out) {
    read_elements(j, field, range, out);
}

bool fills(std::string_view row, std::string_view plain) {
    return plain.starts_with(row) &&
           (plain.size() == row.size() || plain[row.size()] == '.' || plain[row.size()] == '[');
}

void require_object(const Json& j, const std::string& path) {
    if (!j.is_object()) {
        scene_fail(path, "must be an object (got " + json_type_name(j) + ")");
    }
}

void reject_unknown_keys(const Json& j, const std::string& path,
                         std::span<const std::string_view> names) {
    for (const auto& [key, value] : j.items()) {
        if (std::find(names.begin(), names.end(), key) == names.end()) {
            std::string list;
            for (const std::string_view n : names) {
                list += (list.empty() ? "" : ", ") + std::string(n);
            }
            scene_fail(path, "has an unknown field '" + key + "' (known: " + list + ")");
        }
    }
}

} // namespace snow
