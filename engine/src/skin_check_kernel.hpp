#pragma once
// The neighbour list's skin check several particles per instruction: whether some particle
// has moved from its place at the last build by more than the limit. The same squares and
// sum as the scalar check, unfused, so it answers as the scalar check does.
namespace grainlab {

/// True if some particle in [begin, end) lies farther than √limit2 from its reference; both
/// arrays hold x0 y0 x1 y1 ….
bool movedBeyondWide(const double* positions, const double* reference, int begin, int end, double limit2);

}  // namespace grainlab
