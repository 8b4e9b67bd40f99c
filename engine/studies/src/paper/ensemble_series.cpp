#include "grainlab/studies/paper/ensemble_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grainlab/analysis/angles.hpp"

namespace grainlab::report {

std::string Ensemble::label() const {
  AssemblyResult a;
  a.preset = preset;
  a.kind = kind;
  a.beddingDeg = beddingDeg;
  return a.label();
}

std::vector<Ensemble> groupEnsembles(std::span<const AssemblyResult> runs) {
  std::vector<Ensemble> out;
  for (const AssemblyResult& a : runs) {
    auto it = std::find_if(out.begin(), out.end(), [&](const Ensemble& e) { return e.preset == a.preset; });
    if (it == out.end()) {
      out.push_back({a.preset, a.kind, a.beddingDeg, 0, {}});
      it = out.end() - 1;
    }
    ++it->attempted;
    if (a.summary.status == RunStatus::Completed && a.shearing.size() > 0) it->runs.push_back(&a);
  }
  for (Ensemble& e : out) {
    std::stable_sort(e.runs.begin(), e.runs.end(),
                     [](const AssemblyResult* x, const AssemblyResult* y) { return x->seed < y->seed; });
  }
  return out;
}

std::vector<double> atStrains(const AssemblyResult& a, const std::vector<double>& values,
                              const std::vector<double>& strains, bool axial) {
  const auto e = a.shearing.column("axial_strain");
  std::vector<double> out(strains.size(), std::nan(""));
  size_t r = 1;
  for (size_t k = 0; k < strains.size(); ++k) {
    const double s = strains[k];
    if (!std::isfinite(s) || e.empty()) continue;
    if (e.size() == 1 || s == e[0]) {
      if (s == e[0] && !values.empty()) out[k] = values[0];
      continue;
    }
    // Strains ascend in both, so the search resumes where it stopped.
    if (r >= e.size() || !(e[r - 1] <= s)) r = 1;
    while (r < e.size() && !(e[r - 1] <= s && s <= e[r])) ++r;
    if (r >= e.size() || r >= values.size()) continue;
    const double v0 = values[r - 1], v1 = values[r];
    if (s == e[r]) out[k] = v1;
    else if (s == e[r - 1]) out[k] = v0;
    else if (std::isfinite(v0) && std::isfinite(v1) && e[r] > e[r - 1]) {
      const double w = (s - e[r - 1]) / (e[r] - e[r - 1]);
      out[k] = axial ? analysis::axialDeg(v0 + w * analysis::wrapAxialDeg(v1 - v0)) : v0 + w * (v1 - v0);
    }
  }
  return out;
}

std::vector<double> EnsembleBand::mean() const {
  std::vector<double> v;
  for (const MeanInterval& m : stats) v.push_back(m.mean);
  return v;
}
std::vector<double> EnsembleBand::low() const {
  std::vector<double> v;
  for (const MeanInterval& m : stats) v.push_back(m.low);
  return v;
}
std::vector<double> EnsembleBand::high() const {
  std::vector<double> v;
  for (const MeanInterval& m : stats) v.push_back(m.high);
  return v;
}

EnsembleBand ensembleBand(const Ensemble& e, const std::function<std::vector<double>(const AssemblyResult&)>& quantity,
                          bool axial, bool quorum) {
  EnsembleBand b;
  if (e.runs.empty()) return b;
  double end = std::numeric_limits<double>::infinity();
  for (const AssemblyResult* a : e.runs) {
    double last = -std::numeric_limits<double>::infinity();
    for (double s : a->shearing.column("axial_strain")) {
      if (std::isfinite(s)) last = std::max(last, s);
    }
    end = std::min(end, last);
  }
  for (double s : e.runs.front()->shearing.column("axial_strain")) {
    if (std::isfinite(s) && s <= end) b.strain.push_back(s);
  }
  for (const AssemblyResult* a : e.runs) b.perRun.push_back(atStrains(*a, quantity(*a), b.strain, axial));
  const size_t needed = std::max<size_t>(1, (e.runs.size() + 1) / 2);
  for (size_t k = 0; k < b.strain.size(); ++k) {
    std::vector<double> column;
    for (const auto& run : b.perRun) column.push_back(run[k]);
    MeanInterval m = axial ? axialMeanInterval(column) : meanInterval(column);
    if (quorum && static_cast<size_t>(m.n) < needed) m = MeanInterval{m.n, std::nan(""), std::nan(""), std::nan("")};
    b.stats.push_back(m);
  }
  return b;
}

EnsembleBand ensembleColumn(const Ensemble& e, const std::string& column, bool axial) {
  return ensembleBand(e, [&](const AssemblyResult& a) { return a.shearing.column(column); }, axial);
}

}  // namespace grainlab::report
