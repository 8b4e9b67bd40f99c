#pragma once
// The field a scene's refusal names, or "(accepted)": what the scene tests compare, so each
// checks the error names the right key (and gives a reason) rather than only that it throws.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "grainlab/errors.hpp"
#include "grainlab/scene.hpp"

namespace grainlab::testing {

inline std::string refusedField(const nlohmann::json& scene) {
  try {
    parseScene(scene);
  } catch (const SceneError& e) {
    EXPECT_FALSE(e.reason().empty());
    return e.field();
  }
  return "(accepted)";
}

}  // namespace grainlab::testing
