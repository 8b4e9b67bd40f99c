#pragma once
// Where a step's time goes, accumulated over the run (seconds).
namespace grainlab {

struct Profile {
  double neighbors = 0;  ///< neighbour-list rebuilds
  double forces = 0;     ///< contact detection and contact law
  double integrate = 0;  ///< kick and drift, and the check whether the neighbour list must be rebuilt
  long long rebuilds = 0;
  long long featureSearches = 0;  ///< polygon feature searches (the other pair-steps reused features)
};

}  // namespace grainlab
