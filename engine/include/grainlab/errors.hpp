#pragma once
#include <stdexcept>
#include <string>

namespace grainlab {

/// A scene that cannot be run: names the offending field (a JSON path such as
/// "material.friction" or "particles[3].radius") and the reason.
class SceneError : public std::runtime_error {
 public:
  SceneError(std::string field, const std::string& reason)
      : std::runtime_error(field + ": " + reason), field_(std::move(field)), reason_(reason) {}
  const std::string& field() const { return field_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string field_;
  std::string reason_;
};

/// A simulation that cannot go on (non-finite state, runaway overlap): says why.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace grainlab
