/// @file error.hpp
/// @brief snow::Error, the base of everything snow's C++ API throws: its
/// message names the field at fault, and field() gives that name alone.
/// Self-contained.
#pragma once

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

/// A Simulation call refused its arguments (a bad value, a stale or null
/// id, bytes that are not a snapshot of this scene); the simulation is
/// exactly as it was before the call.
class SimulationError : public Error {
  public:
    using Error::Error;
};

/// A GL context, the GL loader, a GPU resource, a shader or an image file failed.
class RenderError : public Error {
  public:
    using Error::Error;
};

} // namespace snow
