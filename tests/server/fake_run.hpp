#pragma once
// A stand-in for grainlab::runScene in unit tests: a tiny real World driven through the
// observer's calls in the engine's order, with as many samples, as much delay and whatever
// ending the test asks for.
#include <chrono>

#include "grainlab/server/serve.hpp"

namespace grainlab::server::testing {

struct FakeRun {
  int samples = 5;
  int stepsPerSample = 10;
  std::chrono::milliseconds delayPerSample{0};
  bool fail = false;  ///< ends `failed` with a reason, as a diverging run does
};

/// The run function; its samples' values are `column index + seq` (step and time exact).
RunFunction fakeRun(FakeRun spec);

}  // namespace grainlab::server::testing
