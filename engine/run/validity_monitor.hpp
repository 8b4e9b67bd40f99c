#pragma once
// The validity envelope checked while the run goes: at each sample, the measured inertial
// number, the mean contact overlap and (in constant-stress shearing) the lateral stress
// against the same limits as before the first step. The first crossing of each limit is
// recorded as a warning with its step. It reads the sample and the world; it never changes
// the simulation.
#include <string>

// A limit counts as crossed once the measured quantity stays past it for this many samples
// in a row: one sample past it can be a servo's transient (a stage's first steps).
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/run.hpp"
#include "grainlab/state_archive.hpp"
#include "grainlab/validity.hpp"

namespace grainlab {

inline constexpr int kCrossingSamples = 3;

class ValidityMonitor {
 public:
  explicit ValidityMonitor(const Scene& scene) : scene_(scene) {}
  /// `first`: the sample a stage starts from (the state the previous stage left).
  void observe(const Sample& sample, const World& world, size_t stageIndex, bool first);
  /// The warnings found before the first step, first in the list.
  void add(const std::vector<ValidityWarning>& warnings) { warnings_.insert(warnings_.end(), warnings.begin(), warnings.end()); }
  const std::vector<ValidityWarning>& warnings() const { return warnings_; }
  void persist(StateArchive& a);

 private:
  void record(const std::string& quantity, double value, const std::string& field, std::int64_t step,
              const std::string& meaning);
  const Scene& scene_;
  std::vector<ContactRecord> contacts_;
  std::vector<ValidityWarning> warnings_;
  std::vector<std::string> crossed_;  // "quantity soft" / "quantity hard": recorded already
  // A crossing under way but not yet kCrossingSamples long: its key, first sample and run length.
  std::vector<std::string> pendingKey_;
  std::vector<ValidityWarning> pending_;
  std::vector<int> pendingSamples_;
};

}  // namespace grainlab
