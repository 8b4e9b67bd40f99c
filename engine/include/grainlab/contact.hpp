#pragma once
// A contact as the outside world sees it (outputs, analysis). The engine's own pair records
// are private; this is a snapshot.
#include "grainlab/math.hpp"

namespace grainlab {

struct ContactRecord {
  int i = 0;          ///< first particle index
  int j = 0;          ///< second particle index, or -1 - wallIndex for a wall contact
  Vec2 point = Vec2::Zero();   ///< contact point, m
  Vec2 normal = Vec2::Zero();  ///< unit normal from i to j
  double fn = 0;      ///< normal force, N per metre; > 0 in compression
  double ft = 0;      ///< tangential force, N per metre: the force on j from i is fn n + ft t,
                      ///< t = n turned +90°
  double overlap = 0; ///< normal overlap, m
  bool isWall() const { return j < 0; }
  int wallIndex() const { return -1 - j; }
};

}  // namespace grainlab
