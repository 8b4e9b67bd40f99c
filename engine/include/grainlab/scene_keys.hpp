#pragma once
// Every key the scene parser accepts, taken from the parser itself: the JsonReader reports
// each key it reads while a set of exemplar scenes (every stage type, disc and polygon
// particles, walls, both assembly shapes, both engines, every preset) is parsed.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace grainlab {

struct SceneKey {
  std::string path;   ///< array indices generalised: "stages[].strain_rate", "particles[].radius"
  std::string kind;   ///< number, integer, boolean, string, choice, vec2, array or object
  /// The value used when the key is omitted, if some exemplar omitted it and the parser used
  /// one fixed value; `defaultDerived` when the omitted value follows from other keys.
  std::optional<nlohmann::json> defaultValue;
  bool defaultDerived = false;
  std::optional<double> min, max;  ///< number/integer bounds (absent: unbounded that side)
  bool minOpen = false, maxOpen = false;
  std::vector<std::string> choices;     ///< choice: the accepted strings
  std::vector<std::string> stageTypes;  ///< stage keys: the stage types that read it
  nlohmann::json example;               ///< a value an exemplar scene gives (null if none does)
};

/// The scenes the catalogue parses, by name: every preset and a scene per parser branch.
std::vector<std::pair<std::string, nlohmann::json>> sceneKeyExemplars();

/// Every key, sorted by path (then by the stage types reading it).
std::vector<SceneKey> sceneKeyCatalogue();

/// The catalogue as JSON: {"keys": [...], "exemplars": [names]}.
nlohmann::json sceneKeyCatalogueJson();

}  // namespace grainlab
