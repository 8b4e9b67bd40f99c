#include "validity_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "grainlab/world.hpp"
#include "validity_reference.hpp"

namespace grainlab {
namespace {

std::string g(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

std::string stageField(size_t k, const char* key) { return "stages[" + std::to_string(k) + "]." + key; }

const char* rateKey(StageSpec::Type t) {
  return t == StageSpec::Type::Rotation ? "deviatoric_strain_rate" : t == StageSpec::Type::SimpleShear ? "shear_rate"
                                                                                                        : "strain_rate";
}

const char* stressKey(StageSpec::Type t) {
  return t == StageSpec::Type::Rotation ? "mean_stress" : t == StageSpec::Type::SimpleShear ? "normal_stress" : "pressure";
}

}  // namespace

void ValidityMonitor::record(const std::string& quantity, double value, const std::string& field, std::int64_t step,
                             const std::string& meaning) {
  const ValidityQuantity& q = validityQuantity(quantity);
  auto past = [&](double limit) { return q.upper ? value > limit : value < limit; };
  for (const auto& [level, limit, reason] : {std::tuple{"soft", q.soft, &q.softReason}, {"hard", q.hard, &q.hardReason}}) {
    const std::string key = quantity + " " + level;
    if (std::count(crossed_.begin(), crossed_.end(), key)) continue;
    const auto at = std::find(pendingKey_.begin(), pendingKey_.end(), key);
    const size_t k = static_cast<size_t>(at - pendingKey_.begin());
    if (!past(limit)) {  // back inside: a crossing under way was a transient
      if (at != pendingKey_.end()) pendingSamples_[k] = 0;
      continue;
    }
    if (at == pendingKey_.end()) {
      pendingKey_.push_back(key);
      pending_.push_back({});
      pendingSamples_.push_back(0);
    }
    // The crossing is reported from its first sample.
    if (pendingSamples_[k]++ == 0)
      pending_[k] = {field, quantity, value, limit, "measured: " + meaning + " (" + *reason + ")", step};
    if (pendingSamples_[k] < kCrossingSamples) continue;
    crossed_.push_back(key);
    warnings_.push_back(pending_[k]);
  }
}

void ValidityMonitor::observe(const Sample& sample, const World& world, size_t stageIndex, bool first) {
  const StageSpec& stage = scene_.stages[stageIndex];
  if (stage.type == StageSpec::Type::Free || first) return;
  const double inertial = sample.values[columnIndex(SeriesColumnId::InertialNumber)];
  if (isShearing(stage.type) && std::isfinite(inertial)) {
    // A rotation in a cell is stress-controlled: its strain rate is the servos', capped there.
    const bool cellRotation = stage.type == StageSpec::Type::Rotation && scene_.boundary.type == BoundarySpec::Type::Periodic;
    const std::string rateField = cellRotation ? "boundary.rate_cap" : stageField(stageIndex, rateKey(stage.type));
    record("inertial_number", inertial, rateField, sample.step,
           "the inertial number is " + g(inertial));
  }
  // The mean overlap of the contacts, over the mean radius of the particles in them.
  if (world.engine() == WorldSettings::Engine::Dem) {
    world.contacts(contacts_);
    double overlap = 0, radius = 0;
    int n = 0;
    for (const ContactRecord& c : contacts_) {
      if (c.isWall()) continue;
      overlap += c.overlap;
      radius += 0.5 * (world.boundingRadii()[c.i] + world.boundingRadii()[c.j]);
      ++n;
    }
    if (n > 0 && radius > 0) {
      // The stress the stage asks for, or the stiffness: whichever is further from the reference.
      const double stressPush = stage.pressure > 0 ? std::log(stage.pressure / reference::kStress) : -1e300;
      const double stiffnessPush = std::log(reference::kNormalStiffness / world.material().normalStiffness);
      const std::string field = stressPush >= stiffnessPush ? stageField(stageIndex, stressKey(stage.type))
                                                            : "material.normal_stiffness";
      record("overlap", overlap / radius, field, sample.step,
             "the mean contact overlap is " + g(overlap / radius) + " of the radius");
    }
  }
  // Constant-stress shearing: is σ11 held?
  const bool heldLaterally = (stage.type == StageSpec::Type::Biaxial || stage.type == StageSpec::Type::Cyclic) &&
                             stage.lateral == StageSpec::Lateral::ConstantStress && stage.pressure > 0;
  const double sigma11 = sample.values[columnIndex(SeriesColumnId::Sigma11)];
  if (heldLaterally && std::isfinite(sigma11)) {
    const double error = std::abs(sigma11 - stage.pressure) / stage.pressure;
    record("lateral_stress_error", error, stageField(stageIndex, "strain_rate"), sample.step,
           "σ11 is " + g(sigma11) + " Pa against the " + g(stage.pressure) + " Pa the stage holds");
  }
}

namespace {

void persistWarnings(StateArchive& a, std::vector<ValidityWarning>& warnings) {
  std::uint64_t n = warnings.size();
  a(n);
  a.require(n <= 100 * validityQuantities().size(), "the validity monitor has " + std::to_string(n) + " warnings");
  if (a.loading()) warnings.resize(n);
  for (ValidityWarning& w : warnings) {
    a(w.field);
    a(w.quantity);
    a(w.value);
    a(w.limit);
    a(w.meaning);
    a(w.step);
  }
}

}  // namespace

void ValidityMonitor::persist(StateArchive& a) {
  a.section("validity monitor");
  a(crossed_);
  persistWarnings(a, warnings_);
  a(pendingKey_);
  persistWarnings(a, pending_);
  a(pendingSamples_);
  a.require(pending_.size() == pendingKey_.size() && pendingSamples_.size() == pendingKey_.size(),
            "the validity monitor's crossings under way do not match");
}

}  // namespace grainlab
