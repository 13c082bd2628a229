/// @file error.hpp
/// @brief The ECS's own error (a stale or null entity, a missing component)
/// and the number format of every error message; snow::Error, their base,
/// is public (<snow/error.hpp>).
#pragma once

#include <sstream>
#include <string>

#include <snow/error.hpp>

namespace snow {

/// A number as error messages print it (6 significant digits).
[[nodiscard]] inline std::string number_text(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

/// Thrown for misuse of entity handles (stale, null) and missing components or resources.
class EcsError : public Error {
  public:
    using Error::Error;
};

} // namespace snow
