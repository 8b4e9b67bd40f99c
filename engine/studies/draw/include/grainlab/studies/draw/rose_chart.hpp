#pragma once
// Rose diagrams: polar histograms of contact normals and of the mean normal and tangential
// contact forces, drawn over the full circle (θ and θ + 180° are the same direction) with the
// fitted c0 + c1 cos 2θ + c2 sin 2θ curve over them.
#include <string>
#include <vector>

#include "grainlab/analysis/histogram.hpp"

namespace grainlab::report {

enum class RoseQuantity {
  Normals,         ///< relative density of contact normals, count·bins/ends (mean 1)
  NormalForce,     ///< mean f_n per bin, N/m
  TangentialForce  ///< mean f_t per bin, N/m (signed; drawn by magnitude, negative bins dashed and unfilled)
};

/// Per bin of `h`: the value drawn (NaN for an empty bin), in the quantity's units.
std::vector<double> roseBinValues(const analysis::PolarHistograms& h, RoseQuantity q);
/// The fitted curve of the quantity at θ (degrees).
double roseFitValue(const analysis::PolarHistograms& h, RoseQuantity q, double thetaDeg);
/// "contact normals", "mean f_n", "mean f_t".
std::string roseName(RoseQuantity q);

/// One column per snapshot (its caption above it, e.g. "ε22 = 5.0 %"), one row per quantity.
/// A null snapshot leaves its column empty with a note. `standalone` adds the XML namespace.
std::string renderRoseGrid(const std::string& id, const std::string& title,
                           const std::vector<const analysis::PolarHistograms*>& snapshots,
                           const std::vector<std::string>& captions, bool standalone = false);

}  // namespace grainlab::report
