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
  // A run stored by grainlab serve (JSON numbers are exact integers up to 2^53).
  from.runId = r.integer("run_id", 0, 1, (1LL << 53));
  r.finish();
  if (!from.run.empty() + !from.checkpoint.empty() + (from.runId != 0) != 1) {
    throw SceneError("start_from", "give one of run (a run's directory, with stage), checkpoint (a file) or run_id "
                                   "(a run stored by grainlab serve, with stage)");
  }
  if (!from.checkpoint.empty() && !from.stage.empty()) {
    throw SceneError("start_from.stage", "a checkpoint file holds one stage's end: give stage only with run");
  }
  return from;
}

}  // namespace grainlab
