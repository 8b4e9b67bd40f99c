#pragma once
#include "grainlab/scene.hpp"
#include "grainlab/stage.hpp"
#include "grainlab/world.hpp"

namespace grainlab {

/// Runs the world untouched for a duration.
class FreeStage : public Stage {
 public:
  FreeStage(const StageSpec& spec, const OutputSpec& output, const World& world)
      : spec_(spec), world_(world), start_(world.time()),
        spacing_(output.sampleInterval > 0 ? output.sampleInterval : spec.duration / 100) {}
  const std::string& name() const override { return spec_.name; }
  bool finished() const override { return elapsed() >= spec_.duration * (1 - 1e-12); }
  double progress() const override { return std::min(1.0, elapsed() / spec_.duration); }
  double sampleCoordinate() const override { return elapsed(); }
  double sampleSpacing() const override { return spacing_; }
  void persist(StateArchive& a) override {
    a(start_);
    a(spacing_);
  }

 private:
  double elapsed() const { return world_.time() - start_; }
  StageSpec spec_;
  const World& world_;
  double start_;
  double spacing_;
};

}  // namespace grainlab
