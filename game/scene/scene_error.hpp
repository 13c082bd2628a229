/// @file scene_error.hpp
/// @brief The internal error of scene loading: a message that names the field
/// (e.g. `nodes[3].extras.snow.surface.cell must be > 0 (got 0)`); the loader
/// prefixes the file name and turns it into SceneLoadResult::error.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace snow {

class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A number as error messages print it (6 significant digits, like check::fail).
[[nodiscard]] inline std::string number_text(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

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
    throw SceneError(field + " " + message);
}

} // namespace snow
