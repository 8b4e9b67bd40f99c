#pragma once
// The error a contact solver throws when a pair overlaps by more than half the smaller disc's
// radius: one message for every solver, so a user reads the same cause and remedy whichever
// contact loop the scene runs in.
#include <cstdint>
#include <sstream>
#include <string>

#include "grainlab/errors.hpp"

namespace grainlab {

/// `i` and `j` are the bodies as users number them (j < 0: wall -1 - j); `fraction` is the
/// overlap over the smaller radius; `whose` names that radius ("particle", "member disc").
[[noreturn]] inline void throwRunawayOverlap(std::int64_t step, int i, int j, double fraction, const char* whose,
                                             double dt, double criticalDt) {
  std::ostringstream os;
  os << "runaway overlap " << (step == 0 ? std::string("at the start") : "at step " + std::to_string(step)) << ": ";
  if (j >= 0) os << "particles " << i << " and " << j;
  else os << "particle " << i << " and wall " << (-1 - j);
  os << " overlap by " << 100 * fraction << "% of the smaller " << whose << "'s radius";
  if (step == 0) {
    os << " at the start (more than 50% is refused: separate the particles in the scene)";
  } else {
    os << "; the contacts are too soft for the load or the timestep (" << dt << " s, critical " << criticalDt
       << " s) is too large";
  }
  throw SimulationError(os.str());
}

}  // namespace grainlab
