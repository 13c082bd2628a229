/// @file error.hpp
/// @brief snow::Error, the base of every exception snow's public API throws
/// (SimulationError, SceneError, RenderError, EcsError): the message names
/// the field at fault, and field() gives that name alone.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace snow {

class Error : public std::runtime_error {
  public:
    /// what() is "<field> <problem>", e.g. "emitter.rate must be >= 0 (got -1)".
    Error(const std::string& field, const std::string& problem)
        : std::runtime_error(field.empty() ? problem : field + " " + problem), field_(field) {}
    /// An error that concerns no single field (a lost GL context, a stale handle).
    explicit Error(const std::string& message) : std::runtime_error(message) {}

    /// The field at fault ("emitter.rate", "nodes[3].extras.snow.surface.cell"),
    /// or empty when the error concerns no single field.
    [[nodiscard]] const std::string& field() const noexcept { return field_; }

  private:
    std::string field_;
};

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
