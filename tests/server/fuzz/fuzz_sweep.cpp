// libFuzzer: any bytes as a `grainlab sweep` spec file. parseSweepSpec checks its form and
// expandSweep builds and validates every run's scene, as `grainlab sweep` does before it runs
// anything. A bad spec must be a SceneError with a reason; nothing may crash,
// hang, allocate without bound or throw anything else.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/studies/sweep_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto json = nlohmann::ordered_json::parse(data, data + size, nullptr, false);
  if (json.is_discarded()) return 0;
  try {
    const auto spec = grainlab::studies::parseSweepSpec(json);
    // A sweep of many runs validates each of their scenes: legitimately slow (64,000 runs
    // of a one-disc scene took over 10 s here under the sanitizers), not a bug. Those are
    // parsed only; parseSweepSpec refuses more than kMaxSweepRuns before anything is built.
    double count = spec.mode == grainlab::studies::SweepMode::Zip ? spec.axes.front().values.size() : 1.0;
    if (spec.mode == grainlab::studies::SweepMode::Grid)
      for (const auto& axis : spec.axes) count *= static_cast<double>(axis.values.size());
    if (count > 1000) return 0;
    const auto runs = grainlab::studies::expandSweep(spec);
    if (runs.empty()) {
      std::cerr << "a sweep spec that passed has no runs\n";
      std::abort();
    }
  } catch (const grainlab::SceneError& e) {
    if (e.reason().empty()) {  // (its field is "" for an unknown key "")
      std::cerr << "SceneError without a reason: " << e.what() << "\n";
      std::abort();
    }
  } catch (const std::exception& e) {
    std::cerr << "the sweep spec threw something other than SceneError: " << e.what() << "\n";
    std::abort();
  }
  return 0;
}
