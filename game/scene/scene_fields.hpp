/// @file scene_fields.hpp
/// @brief Table-driven reading of JSON objects into structs (internal to
/// snow::scene). Each struct has one table: for every field its JSON name, the
/// member it fills, its allowed range and whether it is required. A settings
/// struct of the simulation is read by its own table from settings_fields.hpp
/// (a Schema), plus rows for what needs a reader of its own. read_struct()
/// checks the JSON type, the range and (for `extras.snow`) unknown keys, and
/// every error names the full path of the field.
#pragma once

#include "game/scene/scene_error.hpp"
#include "systems/core/field_rules.hpp"

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
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

/// One row of a struct's table. `range` (systems' Range) bounds a number, or
/// each component of a vector or list.
template <typename T>
struct Field {
    using Struct = T;
    std::string_view name;
    Member<T> member;
    Range range = {};
    bool required = false;
};

/// How a settings struct of the simulation is read: the fields of its systems
/// table (`plain`) by their member's type, and `rows`, each of which fills the
/// plain fields it names (its name, or its name then '.' or '[': a corner
/// "min" fills "min.x" and "min.z") with a reader of its own. Plain fields
/// named in `unread` are not in scenes. Types and JSON shapes are checked
/// here; the ranges of the plain fields are the struct's validate()'s.
template <typename T>
struct Schema {
    std::span<const FieldRule<T>> plain;
    std::span<const Field<T>> rows = {};
    std::span<const std::string_view> unread = {};
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

/// The struct a table (an array of Field<T>, or a Schema<T>) fills.
template <typename Table>
struct table_struct {
    using type = typename std::ranges::range_value_t<Table>::Struct;
};
template <typename T>
struct table_struct<Schema<T>> {
    using type = T;
};
template <typename Table>
using TableStruct = typename table_struct<Table>::type;

/// Whether the row `row` fills the plain field `plain` (see Schema).
[[nodiscard]] bool fills(std::string_view row, std::string_view plain);

/// Fills `out` from the object `j` by the schema: rows, then plain fields in
/// table order; absent optional fields keep `out`'s value.
template <typename T>
void read_fields(const Json& j, const std::string& path, const Schema<T>& schema,
                 UnknownKeys unknown, T& out) {
    require_object(j, path);
    std::vector<std::string_view> names;
    const auto field_of = [&](std::string_view name) {
        return path.empty() ? std::string(name) : path + "." + std::string(name);
    };
    for (const Field<T>& f : schema.rows) {
        names.push_back(f.name);
        const auto it = j.find(f.name);
        if (it == j.end()) {
            if (f.required) {
                scene_fail(field_of(f.name), "is required");
            }
            continue;
        }
        std::visit(
            [&](auto member) {
                if constexpr (std::is_pointer_v<decltype(member)>) {
                    member(*it, field_of(f.name), out);
                } else {
                    read_value(*it, field_of(f.name), f.range, out.*member);
                }
            },
            f.member);
    }
    for (const FieldRule<T>& f : schema.plain) {
        const auto has_row = [&](const Field<T>& row) { return fills(row.name, f.name); };
        if (std::ranges::any_of(schema.rows, has_row) ||
            std::ranges::find(schema.unread, f.name) != schema.unread.end()) {
            continue;
        }
        names.push_back(f.name);
        if (const auto it = j.find(f.name); it != j.end()) {
            std::visit([&](auto member) { read_value(*it, field_of(f.name), {}, out.*member); },
                       f.member);
        }
    }
    if (unknown == UnknownKeys::reject) {
        reject_unknown_keys(j, path, names);
    }
}

/// Fills `out` from the object `j` by the table: rows in table order, absent
/// optional fields keep `out`'s value.
template <typename T, std::size_t N>
void read_fields(const Json& j, const std::string& path, const Field<T> (&fields)[N],
                 UnknownKeys unknown, T& out) {
    read_fields(j, path, Schema<T>{{}, fields}, unknown, out);
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
