/// @file scene_json.hpp
/// @brief Typed, strict reading of the JSON objects in a scene's `extras.snow`
/// (internal to snow::scene). Every error names the full path of the field.
#pragma once

#include "game/scene/scene_error.hpp"

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

using Json = nlohmann::json;

/// The JSON type of a value as a word for error messages ("array", "string", ...).
[[nodiscard]] std::string json_type_name(const Json& j);

/// A finite number that fits a float; throws SceneError naming `field`.
[[nodiscard]] float json_to_float(const Json& j, const std::string& field);
/// An array of exactly three such numbers.
[[nodiscard]] glm::vec3 json_to_vec3(const Json& j, const std::string& field);
/// An integer in [min, max].
[[nodiscard]] std::uint64_t json_to_uint(const Json& j, const std::string& field, std::uint64_t min,
                                         std::uint64_t max);

/// Typed access to the fields of one JSON object. `finish()` rejects keys
/// nobody asked for, so a misspelt field is an error rather than a silent default.
class JsonReader {
  public:
    /// Throws SceneError if `value` is not an object.
    JsonReader(const Json& value, std::string path);

    [[nodiscard]] const std::string& path() const { return path_; }
    /// "path.key", for error messages.
    [[nodiscard]] std::string field(std::string_view key) const;
    [[nodiscard]] bool has(std::string_view key) const;

    // Each read() leaves `out` unchanged when the key is absent.
    void read(std::string_view key, float& out);
    void read(std::string_view key, std::uint64_t& out, std::uint64_t min, std::uint64_t max);
    void read(std::string_view key, std::uint32_t& out, std::uint32_t min, std::uint32_t max);
    void read(std::string_view key, bool& out);
    void read(std::string_view key, std::string& out);
    void read(std::string_view key, glm::vec3& out);
    /// A nested object; nullopt when absent.
    [[nodiscard]] std::optional<JsonReader> object(std::string_view key);
    /// An array (elements unchecked); null when absent.
    [[nodiscard]] const Json* array(std::string_view key);
    /// Any value (unchecked); null when absent.
    [[nodiscard]] const Json* value(std::string_view key) { return take(key); }

    /// Throws SceneError naming the first key that no accessor asked for.
    void finish() const;

  private:
    [[nodiscard]] const Json* take(std::string_view key);

    const Json* value_;
    std::string path_;
    std::vector<std::string> known_;
};

} // namespace snow
