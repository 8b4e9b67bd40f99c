#pragma once
// A scene's specimen made as `grainlab run` makes it (its world, ring or cell, and every stage
// before the first shearing one, run through RunContext without sampling or output), with
// that shearing stage begun: for timing the shearing step itself (grainlab bench --scene
// ring-cell) on exactly what a run would shear.
#include <memory>
#include <ostream>

#include "grainlab/scene.hpp"
#include "grainlab/stage.hpp"
#include "grainlab/world.hpp"

namespace grainlab {

class RunContext;

class PreparedShearing {
 public:
  /// Runs the preparation; throws SceneError (naming `stages`) if the scene has no shearing
  /// stage, and what a run would throw if the scene cannot be built or diverges.
  explicit PreparedShearing(Scene scene, std::ostream* progress = nullptr);
  ~PreparedShearing();
  PreparedShearing(const PreparedShearing&) = delete;
  PreparedShearing& operator=(const PreparedShearing&) = delete;

  World& world();
  const World& world() const;
  /// The shearing stage, begun: step it with beforeStep(), world().step(), afterStep().
  Stage& shearing();
  /// The specimen's void ratio now, as series.csv's void_ratio measures it.
  double voidRatio() const;

 private:
  Scene scene_;  // the context refers to it
  std::unique_ptr<RunContext> context_;
};

}  // namespace grainlab
