/// @file scene_fields.hpp
/// @brief Table-driven reading of JSON objects into structs (internal to
/// snow::scene). Each struct has one table: for every field its JSON name, the
/// member it fills, its allowed range and whether it is required. read_struct()
/// checks the JSON type, the range and (for `extras.snow`) unknown keys, and
/// every error names the full path of the field.
#pragma once

#include "game/scene/scene_error.hpp"

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <ranges>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace snow {

using Json = nlohmann::json;

/// The JSON type of a value as a word for error messages ("array", "string", ...).
[[nodiscard]] std::string json_type_name(const Json& j);

/// Allowed values of a number (of each component of a vector or list).
struct Range {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_exclusive = false; ///< true: > min; false: >= min
};
inline constexpr Range above_zero{0.0, std::numeric_limits<double>::infinity(), true};
inline constexpr Range at_least_zero{0.0};

/// A field that needs more than a value check (a choice of names, a nested
/// object or list): reads `value` into the struct; `field` names it in errors.
template <typename T>
using FieldReader = void (*)(const Json& value, const std::string& field, T& out);

/// The members a field can fill.
template <typename T>
using Member =
    std::variant<float T::*, double T::*, bool T::*, std::uint32_t T::*, std::uint64_t T::*,
                 std::optional<std::uint64_t> T::*, std::string T::*,
                 std::optional<std::string> T::*, glm::vec3 T::*, std::vector<double> T::*,
                 std::vector<std::uint64_t> T::*, std::vector<std::string> T::*, FieldReader<T>>;

/// One row of a struct's table.
template <typename T>
struct Field {
    using Struct = T;
    std::string_view name;
    Member<T> member;
    Range range = {};
    bool required = false;
};

/// What to do with keys no row names: `extras.snow` rejects them (a typo never
/// becomes a silent default); glTF's own objects ignore them (the format has
/// many properties the loader does not use, and extensions anywhere).
enum class UnknownKeys : std::uint8_t { reject, ignore };

// One value into one member; `field` names it in errors. Numbers must be
// finite (and fit a float where the member is one) and lie in `range`;
// integers must be integral and fit the member.
void read_value(const Json& j, const std::string& field, const Range& range, float& out);
void read_value(const Json& j, const std::string& field, const Range& range, double& out);
void read_value(const Json& j, const std::string& field, const Range& range, bool& out);
void read_value(const Json& j, const std::string& field, const Range& range, std::uint32_t& out);
void read_value(const Json& j, const std::string& field, const Range& range, std::uint64_t& out);
void read_value(const Json& j, const std::string& field, const Range& range,
                std::optional<std::uint64_t>& out);
void read_value(const Json& j, const std::string& field, const Range& range, std::string& out);
void read_value(const Json& j, const std::string& field, const Range& range,
                std::optional<std::string>& out);
void read_value(const Json& j, const std::string& field, const Range& range, glm::vec3& out);
void read_value(const Json& j, const std::string& field, const Range& range,
                std::vector<double>& out);
void read_value(const Json& j, const std::string& field, const Range& range,
                std::vector<std::uint64_t>& out);
void read_value(const Json& j, const std::string& field, const Range& range,
                std::vector<std::string>& out);

/// Throws SceneError unless `j` is an object.
void require_object(const Json& j, const std::string& path);
/// Throws SceneError naming the first key of `j` that is not in `names`.
void reject_unknown_keys(const Json& j, const std::string& path,
                         std::span<const std::string_view> names);

/// The struct a table (an array of Field<T>) fills.
template <typename Table>
using TableStruct = typename std::ranges::range_value_t<Table>::Struct;

/// Fills `out` from the object `j` by the table: rows in table order, absent
/// optional fields keep `out`'s value.
template <typename Table>
void read_fields(const Json& j, const std::string& path, const Table& fields, UnknownKeys unknown,
                 TableStruct<Table>& out) {
    require_object(j, path);
    std::vector<std::string_view> names;
    for (const auto& f : fields) {
        names.push_back(f.name);
        const auto it = j.find(f.name);
        const std::string field =
            path.empty() ? std::string(f.name) : path + "." + std::string(f.name);
        if (it == j.end()) {
            if (f.required) {
                scene_fail(field, "is required");
            }
            continue;
        }
        std::visit(
            [&](auto member) {
                if constexpr (std::is_pointer_v<decltype(member)>) {
                    member(*it, field, out);
                } else {
                    read_value(*it, field, f.range, out.*member);
                }
            },
            f.member);
    }
    if (unknown == UnknownKeys::reject) {
        reject_unknown_keys(j, path, names);
    }
}

/// A struct read from the object `j`, starting from its defaults.
template <typename Table>
[[nodiscard]] TableStruct<Table> read_struct(const Json& j, const std::string& path,
                                             const Table& fields, UnknownKeys unknown) {
    TableStruct<Table> out{};
    read_fields(j, path, fields, unknown, out);
    return out;
}

/// Each element of the array `j` read as a struct; `path` is the array's name.
template <typename Table>
[[nodiscard]] std::vector<TableStruct<Table>> read_list(const Json& j, const std::string& path,
                                                        const Table& fields, UnknownKeys unknown) {
    if (!j.is_array()) {
        scene_fail(path, "must be an array (got " + json_type_name(j) + ")");
    }
    std::vector<TableStruct<Table>> out;
    out.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        out.push_back(read_struct(j[i], path + "[" + std::to_string(i) + "]", fields, unknown));
    }
    return out;
}

template <typename>
struct member_class;
template <typename C, typename M>
struct member_class<M C::*> {
    using type = C;
};
template <typename T>
inline constexpr bool is_vector = false;
template <typename T, typename A>
inline constexpr bool is_vector<std::vector<T, A>> = true;

/// A FieldReader for a nested object read by `Table` into `Member` (a struct
/// or an optional one), or for an array of them into a vector `Member`.
template <auto Member, const auto& Table, UnknownKeys Unknown>
void read_nested(const Json& j, const std::string& field,
                 typename member_class<decltype(Member)>::type& out) {
    if constexpr (is_vector<std::remove_cvref_t<decltype(out.*Member)>>) {
        out.*Member = read_list(j, field, Table, Unknown);
    } else {
        out.*Member = read_struct(j, field, Table, Unknown);
    }
}

/// A string that must be one of the names in `choices` (pairs of name and
/// value); returns that name's value.
template <typename Choices>
[[nodiscard]] auto read_choice(const Json& j, const std::string& field, const Choices& choices) {
    std::string list;
    for (const auto& [name, value] : choices) {
        if (j.is_string() && j.get<std::string>() == name) {
            return value;
        }
        list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    }
    scene_fail(field, "must be one of " + list + " (got " +
                          (j.is_string() ? in_quotes(j.get<std::string>()) : json_type_name(j)) +
                          ")");
}

} // namespace snow
