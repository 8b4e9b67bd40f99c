#pragma once
// Writes the rose data of a headless run (scene "output": {"histograms": true}, the default)
// to DIR/histograms.csv, one row per (sample, quantity, bin):
//   stage,sample,quantity,bin,value
// `sample` counts series.csv's rows from 0, so row k of series.csv and sample k here are the
// same instant. `bin` b covers directions [b, b + 1) · 180°/bins. The quantities are what the
// dashboard's rose diagrams draw (engine/analysis/histogram.hpp):
//   count             contact ends in the bin
//   density           count · bins / ends: 1 everywhere for an isotropic sample
//   fn, ft, ln, lt    the mean of f_n, f_t (N/m), l_n, l_t (m) over the bin's ends; empty
//                     for an empty bin
//   <q>_fit           the fitted c0 + c1 cos 2θ + c2 sin 2θ of density, fn, ft, ln, lt at
//                     the bin's centre
// Samples with no contacts have no rows. It reads the samples, never the simulation.
#include <cstdint>
#include <fstream>
#include <string>

#include "grainlab/run.hpp"

namespace grainlab {

class HistogramWriter : public RunObserver {
 public:
  explicit HistogramWriter(std::string directory);
  void onStart(const Scene&, const World&) override;
  void onSample(const Sample&, const World&) override;
  /// Checkpoints: the file's length and the sample count, the rows flushed to disk first.
  void persistOutput(StateArchive& a) override;
  /// Rows written after the checkpoint are cut off (they are written again).
  void onResume(const Scene&, const World&) override;
  void onFinish(const RunSummary&, const World&) override;

 private:
  void append(const std::string& text);

  std::string path_;
  std::ofstream file_;
  std::int64_t samples_ = 0;
  std::uint64_t bytes_ = 0;  // at the checkpoint being loaded
};

/// The header line of histograms.csv.
std::string histogramsHeader();

}  // namespace grainlab
