#pragma once
// Where a run posted with "start_from": {"run_id": N, "stage": S} starts: the end of stage S
// that run N kept in this server's own storage (docs/prepared-specimens.md). A request never
// names a file here: a client's start_from.run or start_from.checkpoint is refused.
//
// Each run keeps its stages' ends in <checkpoint dir>/run-ID/stages/ (runScene's stage
// directory). A run that starts from one gets its own hard link (or copy) of it,
// run-ID/specimen.checkpoint, made before the run is accepted and checked there: the bytes
// checked are the bytes run, and deleting the parent later does not pull them away.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "grainlab/scene.hpp"
#include "run_record.hpp"

namespace grainlab::server {

/// A stage checkpoint linked into the checkpoint directory for a run being admitted; removed
/// unless adopt() gives it to the stored run.
class StagedSpecimen {
 public:
  StagedSpecimen() = default;
  explicit StagedSpecimen(std::string path) : path_(std::move(path)) {}
  StagedSpecimen(StagedSpecimen&& other) noexcept : path_(std::move(other.path_)) { other.path_.clear(); }
  StagedSpecimen& operator=(StagedSpecimen&&) = delete;
  ~StagedSpecimen();
  const std::string& path() const { return path_; }
  /// Hands the file over (it is not removed any more).
  std::string release();

 private:
  std::string path_;
};

class SpecimenSource {
 public:
  explicit SpecimenSource(std::string checkpointDir) : dir_(std::move(checkpointDir)) {}

  /// Run `id`'s folder: its stages' ends (stages/) and the specimen it started from.
  std::string runFolder(std::int64_t id) const;
  /// run-ID/specimen.checkpoint: run `id`'s own copy of the stage checkpoint it started from.
  std::string startedFromPath(std::int64_t id) const;

  /// For a scene with start_from: refuses a file path (400, start_from.run or
  /// start_from.checkpoint), finds the stage checkpoint `parent` kept (its stage, or the stage
  /// before the scene's first shearing stage) and links it into the checkpoint directory; the
  /// scene is pointed at that link. `parent` is the stored run start_from.run_id names, with
  /// its live status, or nothing if there is none. Throws ApiError naming the field: 400 for a
  /// run or stage there is not, or a stage whose end the run did not keep; 409 for a run that
  /// is queued or running and has not ended that stage yet.
  StagedSpecimen stage(Scene& scene, const std::optional<RunRecord>& parent, RunOrigin& origin) const;
  /// Moves the staged link to run `id`'s folder and points the scene at it.
  void adopt(Scene& scene, StagedSpecimen& staged, std::int64_t id) const;
  /// A stored run that started from a specimen, parsed again (queued again after a restart):
  /// points its scene at its own copy.
  void pointAtOwnCopy(Scene& scene, std::int64_t id) const;
  /// The stages of run `record` whose end is kept here, in the order they ran: the stages a
  /// run can start from.
  std::vector<std::string> keptStages(const RunRecord& record) const;
  /// `reason` with the server's own path of the scene's specimen replaced by what it is.
  std::string withoutPaths(const std::string& reason, const Scene& scene, const RunOrigin& origin) const;
  /// Removes run `id`'s folder (its stages' ends and its specimen).
  void remove(std::int64_t id) const;
  /// Removes staged links left by a server that stopped while admitting a run.
  void removeStale() const;

 private:
  std::string dir_;
};

}  // namespace grainlab::server
