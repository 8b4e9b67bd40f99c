#pragma once
// Several observers watching one run (the output files and the VTK frames, say): each call
// goes to each of them in the order given; the run is cancelled if any of them asks, and takes
// the threads any of them is lent.
#include <algorithm>
#include <initializer_list>
#include <vector>

#include "grainlab/run.hpp"

namespace grainlab {

class ObserverTee : public RunObserver {
 public:
  ObserverTee() = default;
  ObserverTee(std::initializer_list<RunObserver*> observers) : observers_(observers) {}
  void add(RunObserver& observer) { observers_.push_back(&observer); }

  void onEstimate(const RunCost& cost) override {
    for (RunObserver* o : observers_) o->onEstimate(cost);
  }
  void onWarnings(const std::vector<ValidityWarning>& warnings) override {
    for (RunObserver* o : observers_) o->onWarnings(warnings);
  }
  void onStart(const Scene& scene, const World& world) override {
    for (RunObserver* o : observers_) o->onStart(scene, world);
  }
  void onSample(const Sample& sample, const World& world) override {
    for (RunObserver* o : observers_) o->onSample(sample, world);
  }
  void onProgress(double fraction, std::string_view stage, const World& world) override {
    for (RunObserver* o : observers_) o->onProgress(fraction, stage, world);
  }
  bool cancelRequested() override {
    bool cancel = false;
    for (RunObserver* o : observers_) cancel = o->cancelRequested() || cancel;
    return cancel;
  }
  bool stopRequested() override {
    bool stop = false;
    for (RunObserver* o : observers_) stop = o->stopRequested() || stop;
    return stop;
  }
  /// The most any of them was lent: one lender is enough.
  int threadsLent() override {
    int lent = 0;
    for (RunObserver* o : observers_) lent = std::max(lent, o->threadsLent());
    return lent;
  }
  void persistOutput(StateArchive& a) override {
    for (RunObserver* o : observers_) o->persistOutput(a);
  }
  void onResume(const Scene& scene, const World& world) override {
    for (RunObserver* o : observers_) o->onResume(scene, world);
  }
  void onFinish(const RunSummary& summary, const World& world) override {
    for (RunObserver* o : observers_) o->onFinish(summary, world);
  }

 private:
  std::vector<RunObserver*> observers_;
};

}  // namespace grainlab
