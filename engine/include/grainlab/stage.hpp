#pragma once
// A stage of a run: what drives the boundary between steps, and when it is over.
#include <string>

#include "grainlab/state_archive.hpp"

namespace grainlab {

class Stage {
 public:
  virtual ~Stage() = default;
  virtual const std::string& name() const = 0;
  /// Before each World::step: set the boundary's kinematic velocities.
  virtual void beforeStep() {}
  /// After each World::step: update the stage's own measures (strain, servo state).
  virtual void afterStep() {}
  virtual bool finished() const = 0;
  /// Fraction of the stage done, in [0, 1] (an estimate where the end is a criterion).
  virtual double progress() const = 0;
  /// Relative share of the whole run's work, for overall progress.
  virtual double work() const { return 1.0; }
  /// Samples are taken each time this coordinate (s of time, or axial strain) advances by
  /// sampleSpacing().
  virtual double sampleCoordinate() const = 0;
  virtual double sampleSpacing() const = 0;
  /// Said of a stage that ended otherwise than by its own criterion (e.g. at its time
  /// limit); empty if it ended normally. Recorded in the run's summary.
  virtual std::string endNote() const { return {}; }
  /// Checkpoints: the stage's own state (servo integrals, where it started, what it has
  /// decided), saved, or loaded into the same stage rebuilt on the resumed world. Every
  /// member that changes after construction, or that construction read from the world,
  /// belongs here: a resumed stage must decide exactly as the saved one would have.
  virtual void persist(StateArchive& a) = 0;
};

}  // namespace grainlab
