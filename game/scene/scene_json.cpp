// Strict typed reads from nlohmann::json for the scene schema. The JSON is
// parsed by the loader itself (not via tinygltf::Value, which truncates
// integers to int and drops nulls), so types and values are exactly the file's.
#include "game/scene/scene_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

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

float json_to_float(const Json& j, const std::string& field) {
    if (!j.is_number()) {
        scene_fail(field, "must be a number (got " + json_type_name(j) + ")");
    }
    const double v = j.get<double>();
    if (!std::isfinite(v) || std::abs(v) > std::numeric_limits<float>::max()) {
        scene_fail(field,
                   "must be a finite number within float range (got " + number_text(v) + ")");
    }
    return static_cast<float>(v);
}

glm::vec3 json_to_vec3(const Json& j, const std::string& field) {
    if (!j.is_array() || j.size() != 3) {
        scene_fail(field,
                   "must be an array of 3 numbers (got " +
                       (j.is_array() ? "array of " + std::to_string(j.size()) : json_type_name(j)) +
                       ")");
    }
    return {json_to_float(j[0], field + "[0]"), json_to_float(j[1], field + "[1]"),
            json_to_float(j[2], field + "[2]")};
}

std::uint64_t json_to_uint(const Json& j, const std::string& field, std::uint64_t min,
                           std::uint64_t max) {
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "[" + std::string&&.
    std::string range = "in [";
    range += std::to_string(min);
    range += ", ";
    range += std::to_string(max);
    range += "]";
    if (j.is_number_unsigned()) {
        const auto v = j.get<std::uint64_t>();
        if (v < min || v > max) {
            scene_fail(field, "must be " + range + " (got " + std::to_string(v) + ")");
        }
        return v;
    }
    if (j.is_number_integer()) { // negative (non-negative ones parse as unsigned)
        scene_fail(field,
                   "must be " + range + " (got " + std::to_string(j.get<std::int64_t>()) + ")");
    }
    if (j.is_number()) {
        scene_fail(field, "must be an integer (got " + number_text(j.get<double>()) + ")");
    }
    scene_fail(field, "must be an integer (got " + json_type_name(j) + ")");
}

JsonReader::JsonReader(const Json& value, std::string path)
    : value_(&value), path_(std::move(path)) {
    if (!value.is_object()) {
        scene_fail(path_, "must be an object (got " + json_type_name(value) + ")");
    }
}

std::string JsonReader::field(std::string_view key) const {
    return path_ + "." + std::string(key);
}

bool JsonReader::has(std::string_view key) const {
    return value_->contains(key);
}

const Json* JsonReader::take(std::string_view key) {
    known_.emplace_back(key);
    const auto it = value_->find(key);
    return it == value_->end() ? nullptr : &*it;
}

void JsonReader::read(std::string_view key, float& out) {
    if (const Json* j = take(key)) {
        out = json_to_float(*j, field(key));
    }
}

void JsonReader::read(std::string_view key, std::uint64_t& out, std::uint64_t min,
                      std::uint64_t max) {
    if (const Json* j = take(key)) {
        out = json_to_uint(*j, field(key), min, max);
    }
}

void JsonReader::read(std::string_view key, std::uint32_t& out, std::uint32_t min,
                      std::uint32_t max) {
    if (const Json* j = take(key)) {
        out = static_cast<std::uint32_t>(json_to_uint(*j, field(key), min, max));
    }
}

void JsonReader::read(std::string_view key, bool& out) {
    if (const Json* j = take(key)) {
        if (!j->is_boolean()) {
            scene_fail(field(key), "must be true or false (got " + json_type_name(*j) + ")");
        }
        out = j->get<bool>();
    }
}

void JsonReader::read(std::string_view key, std::string& out) {
    if (const Json* j = take(key)) {
        if (!j->is_string()) {
            scene_fail(field(key), "must be a string (got " + json_type_name(*j) + ")");
        }
        out = j->get<std::string>();
    }
}

void JsonReader::read(std::string_view key, glm::vec3& out) {
    if (const Json* j = take(key)) {
        out = json_to_vec3(*j, field(key));
    }
}

std::optional<JsonReader> JsonReader::object(std::string_view key) {
    if (const Json* j = take(key)) {
        return JsonReader(*j, field(key));
    }
    return std::nullopt;
}

const Json* JsonReader::array(std::string_view key) {
    const Json* j = take(key);
    if (j != nullptr && !j->is_array()) {
        scene_fail(field(key), "must be an array (got " + json_type_name(*j) + ")");
    }
    return j;
}

void JsonReader::finish() const {
    for (const auto& [key, value] : value_->items()) {
        if (std::find(known_.begin(), known_.end(), key) == known_.end()) {
            std::string list;
            for (const std::string& k : known_) {
                list += (list.empty() ? "" : ", ") + k;
            }
            scene_fail(path_, "has an unknown field '" + key + "' (known: " + list + ")");
        }
    }
}

} // namespace snow
