/// @file scene_error.hpp
/// @brief The internal error of scene loading: a message that names the field
/// (e.g. `nodes[3].extras.snow.surface.cell must be > 0 (got 0)`); the loader
/// prefixes the file name and turns it into SceneLoadResult::error.
#pragma once

#include "ecs/error.hpp"

#include <string>

namespace snow {

class SceneError : public Error {
  public:
    using Error::Error;
};

/// `"text"` with the quotes, for error messages. (Built by appending: GCC 12
/// warns falsely, -Wrestrict, on `"\"" + std::string&&`.)
[[nodiscard]] inline std::string in_quotes(const std::string& text) {
    std::string out(1, '"');
    out += text;
    out += '"';
    return out;
}

/// Throws SceneError("field message").
[[noreturn]] inline void scene_fail(const std::string& field, const std::string& message) {
    throw SceneError(field, message);
}

} // namespace snow
