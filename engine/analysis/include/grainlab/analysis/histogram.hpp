#pragma once
// Polar histograms of contact ends: normals folded into [0°, 180°) (θ and θ + 180° are the same
// direction), with the per-bin means of f_n, f_t, l_n, l_t and a fitted c0 + c1 cos 2θ + c2 sin 2θ
// curve for each: the paper's "regression of histogram data", for display and as a check on
// measureFabric. The same ends as measureFabric and contactStress (contact_ends.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "grainlab/analysis/fabric.hpp"
#include "grainlab/contact.hpp"
#include "grainlab/math.hpp"
#include "grainlab/periodic_cell.hpp"

namespace grainlab::analysis {

/// value(θ) = c0 + c1 cos 2θ + c2 sin 2θ, in the units of the data it was fitted to.
struct FourierFit {
  double c0 = 0, c1 = 0, c2 = 0;
  /// The curve at θ (degrees).
  double value(double thetaDeg) const;
  /// √(c1² + c2²): the second-harmonic amplitude as fitted (still shrunk by the binning).
  double amplitude() const;
  /// θ_k (degrees, [0, 180)) of a curve written c0 + a cos 2(θ − θ_k): f_n, l_n, the density.
  double cosDirectionDeg() const;
  /// θ_k (degrees, [0, 180)) of a curve written c0 − a sin 2(θ − θ_k): f_t, l_t.
  double sinDirectionDeg() const;
};

/// Minimum number of bins: coarser histograms smear the directions the paper reads off them.
inline constexpr int kMinHistogramBins = 18;
/// Maximum number of bins accepted (a bound on the buffers, not a physical limit).
inline constexpr int kMaxHistogramBins = 3600;

struct PolarHistograms {
  /// Number of bins over [0, 180); set it before measureHistograms (at least 18).
  int bins = kMinHistogramBins;
  std::int64_t ends = 0;      ///< contact ends counted (the sum of `count`)
  std::int64_t contacts = 0;  ///< contacts with at least one counted end
  std::vector<std::int64_t> count;  ///< ends per bin; bin b covers [b Δ, (b + 1) Δ), Δ = 180°/bins
  std::vector<double> fn;  ///< N/m: mean normal force of the ends in each bin (0 if the bin is empty)
  std::vector<double> ft;  ///< N/m: mean tangential force per bin (0 if empty)
  std::vector<double> ln;  ///< m: mean normal branch component per bin (0 if empty)
  std::vector<double> lt;  ///< m: mean tangential branch component per bin (0 if empty)
  /// Fitted to the relative density count·bins/ends (dimensionless, mean 1): ≈ 1 + a_c s cos 2(θ − θ_c).
  FourierFit density;
  FourierFit fnFit;  ///< N/m, fitted to the non-empty bins' f_n means
  FourierFit ftFit;  ///< N/m
  FourierFit lnFit;  ///< m
  FourierFit ltFit;  ///< m

  double binWidthDeg() const { return 180.0 / bins; }  ///< Δ, degrees
  double binCentreDeg(int b) const { return (b + 0.5) * binWidthDeg(); }  ///< degrees
  /// The bin of an axial direction θ (degrees, any value; folded into [0, 180) first).
  int binOf(double thetaDeg) const;
  /// sin Δ / Δ (Δ in radians): the factor by which binning shrinks a cos 2θ amplitude.
  double smoothing() const;
  /// The anisotropy read off the fits, each amplitude divided by smoothing(): a_c, θ_c from
  /// `density`; f0, a_n, θ_n from fnFit; a_t, θ_t, a_w_direct from ftFit; l0, a_ln, θ_ln from
  /// lnFit; a_lt, θ_lt, lt0_ratio from ltFit; a_w from moment equilibrium. Units as FabricState.
  FabricState anisotropy() const;
};

/// Fills `out` (reusing its buffers when out.bins has not changed) from the contact ends of
/// particles with inside != 0. Throws std::invalid_argument if out.bins is outside
/// [kMinHistogramBins, kMaxHistogramBins] or inside and centroids differ in size, and
/// std::out_of_range for a contact naming a particle that does not exist.
void measureHistograms(std::span<const ContactRecord> contacts, std::span<const Vec2> centroids,
                       std::span<const unsigned char> inside, PolarHistograms& out,
                       const PeriodicCell* cell = nullptr);

/// {"bins", "bin_width_deg", "smoothing", "ends", "contacts", "centres_deg": [...], "count": [...],
///  "fn"/"ft"/"ln"/"lt": [mean or null for an empty bin], "fits": {"density"|"fn"|"ft"|"ln"|"lt":
///  {"c0", "c1", "c2"}}}. Degrees, N/m and m, as in the struct.
void to_json(nlohmann::json& j, const PolarHistograms& h);
/// Reads what to_json writes (bins, ends, contacts, count, the means, the fits; the derived
/// fields are recomputed). Throws nlohmann::json::exception or std::invalid_argument if the
/// arrays do not have `bins` entries.
void from_json(const nlohmann::json& j, PolarHistograms& h);

}  // namespace grainlab::analysis
