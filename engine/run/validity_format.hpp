#pragma once
// How the validity envelope prints a quantity, a limit or a field's value in its messages:
// three significant digits, enough to see how far past a limit a scene is.
#include <cstdio>
#include <string>

namespace grainlab {

inline std::string threeSignificant(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

}  // namespace grainlab
