#pragma once
// The Pareto plot of `grainlab tradeoff`: error against cost, one panel per preset, as a
// standalone SVG written by hand (log-scaled time, linear error, the front as a staircase).
#include <string>
#include <vector>

#include "grainlab/studies/tradeoff/pareto_panel.hpp"

namespace grainlab::tradeoff {

/// The panels side by side in one <svg> document.
std::string renderParetoSvg(const std::vector<ParetoPanel>& panels, const std::string& xLabel,
                            const std::string& yLabel);

}  // namespace grainlab::tradeoff
