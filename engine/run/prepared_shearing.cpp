#include "grainlab/prepared_shearing.hpp"

#include <cstdint>

#include "grainlab/errors.hpp"
#include "grainlab/stages.hpp"
#include "run_context.hpp"

namespace grainlab {

PreparedShearing::PreparedShearing(Scene scene, std::ostream* progress) : scene_(std::move(scene)) {
  size_t shearing = 0;
  while (shearing < scene_.stages.size() && !isShearing(scene_.stages[shearing].type)) ++shearing;
  if (shearing == scene_.stages.size()) throw SceneError("stages", "has no shearing stage to prepare for");
  context_ = std::make_unique<RunContext>(scene_);
  World& w = context_->world();
  for (size_t k = 0; k < shearing; ++k) {
    if (progress) *progress << scene_.name << ": " << scene_.stages[k].name << "\n";
    Stage& stage = context_->beginStage(k);
    for (std::int64_t n = 1; !stage.finished(); ++n) {
      stage.beforeStep();
      w.step();
      stage.afterStep();
      if (n % 1000 == 0) w.checkHealth();
    }
    context_->endStage();
  }
  w.checkHealth();
  context_->beginStage(shearing);
}

PreparedShearing::~PreparedShearing() = default;

World& PreparedShearing::world() { return context_->world(); }
const World& PreparedShearing::world() const { return context_->world(); }
Stage& PreparedShearing::shearing() { return context_->stage(); }
double PreparedShearing::voidRatio() const { return context_->voidRatioNow(); }

}  // namespace grainlab
