#pragma once
// Synthetic assemblies for the findings' tests: shearing series built from closed forms, so
// each test knows the answer the evaluators must give.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "grainlab/studies/paper/assembly_result.hpp"

namespace grainlab::report::testing {

/// A completed run of `kind` with `samples` rows from ε22 = 0 to 0.2, 2,500 contacts (noise
/// floor 0.035), a symmetric stress with φ_mob rising to a peak at 10 % and falling, and
/// quiet defaults for every other column; `column` then overrides columns as functions of ε.
inline AssemblyResult syntheticRun(AssemblyKind kind, double beddingDeg = 0, int samples = 81) {
  AssemblyResult a;
  a.kind = kind;
  a.beddingDeg = beddingDeg;
  a.preset = kind == AssemblyKind::Circular ? "circular" : kind == AssemblyKind::Random
                                                               ? "elongated-random"
                                                               : "elongated-bedding-" + std::to_string(static_cast<int>(beddingDeg));
  a.summary.status = RunStatus::Completed;
  a.summary.particles = 2000;
  a.summary.voidRatioAfterConsolidation = 0.27;
  std::vector<double> strain;
  for (int k = 0; k < samples; ++k) strain.push_back(0.2 * k / (samples - 1));
  auto fill = [&](const std::string& name, const std::function<double(double)>& f) {
    std::vector<double> v;
    for (double e : strain) v.push_back(f(e));
    a.shearing.setColumn(name, v);
  };
  fill("axial_strain", [](double e) { return e; });
  fill("contacts", [](double) { return 2500.0; });
  fill("p", [](double) { return 300e3; });
  fill("sigma11", [](double) { return 300e3; });
  fill("sigma12", [](double) { return 1e3; });
  fill("sigma21", [](double) { return 1e3; });
  fill("phi_mob_deg", [](double e) { return e == 0 ? 0.5 : 30 - 1500 * (e - 0.1) * (e - 0.1) + 3; });
  for (const char* t : {"c", "n", "t"}) {
    fill(std::string("a_") + t, [](double e) { return 0.1 + 2 * e; });
    fill(std::string("theta_") + t + "_deg", [](double e) { return 90 + 30 * std::exp(-e / 0.04); });
  }
  for (const char* t : {"ln", "lt"}) {
    fill(std::string("a_") + t, [](double) { return 0.0; });
    fill(std::string("theta_") + t + "_deg", [](double) { return 0.0; });
  }
  for (const char* c : {"omega_macro_deg", "omega_micro_deg", "omega_eq10_deg", "omega_eq11_deg"}) {
    fill(c, [](double e) { return 8 * std::exp(-e / 0.05); });
  }
  return a;
}

/// Replaces a column by f(ε).
inline void setColumn(AssemblyResult& a, const std::string& name, const std::function<double(double)>& f) {
  std::vector<double> v;
  for (double e : a.shearing.column("axial_strain")) v.push_back(f(e));
  a.shearing.setColumn(name, v);
}

}  // namespace grainlab::report::testing
