// libFuzzer: any bytes given to POST /api/runs go through JSON parsing and parseScene. A bad
// scene must be a SceneError with a reason (its field is the JSON path, which is "" for an
// unknown key "" at the top); nothing may crash, hang or throw anything else.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/scene.hpp"
#include "run_service.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto json = nlohmann::json::parse(data, data + size, nullptr, false);
  if (json.is_discarded()) return 0;
  try {
    const auto scene = grainlab::parseScene(json);
    (void)grainlab::server::estimateParticles(scene);
  } catch (const grainlab::SceneError& e) {
    if (e.reason().empty()) {
      std::cerr << "SceneError without a reason: " << e.what() << "\n";
      std::abort();
    }
  } catch (const std::exception& e) {
    std::cerr << "parseScene threw something other than SceneError: " << e.what() << "\n";
    std::abort();
  }
  return 0;
}
