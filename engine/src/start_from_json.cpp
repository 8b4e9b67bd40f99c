#include "start_from_json.hpp"

#include "json_reader.hpp"

namespace grainlab {

std::optional<StartFrom> parseStartFrom(const nlohmann::json& json) {
  if (json.is_null()) return std::nullopt;
  JsonReader r(json, "start_from");
  StartFrom from;
  from.run = r.string("run", "");
  from.stage = r.string("stage", "");
  from.checkpoint = r.string("checkpoint", "");
  r.finish();
  if (from.run.empty() == from.checkpoint.empty()) {
    throw SceneError("start_from", "give either run (a run's directory, with stage) or checkpoint (a file)");
  }
  if (!from.checkpoint.empty() && !from.stage.empty()) {
    throw SceneError("start_from.stage", "a checkpoint file holds one stage's end: give stage only with run");
  }
  return from;
}

}  // namespace grainlab
