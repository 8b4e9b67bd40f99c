#pragma once
#include <string>
#include <vector>

namespace grainlab {

/// `grainlab bench`: particle-steps per second on settled piles of ~2,500 discs and ~2,500
/// polygons (the median of several timed repeats, after settling).
int benchCommand(const std::vector<std::string>& args);

}  // namespace grainlab
