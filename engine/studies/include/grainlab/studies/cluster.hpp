#pragma once
// The MPI world this process is part of: the ranks started by mpirun or srun, or a world
// of one. MPI is initialised only when an MPI launcher started the process, so a plain
// `grainlab sweep` (or a build without MPI) never touches it.
namespace grainlab::studies {

class Cluster {
 public:
  enum class Join {
    Launcher,  ///< the launcher's MPI world if there is one
    Alone,     ///< a world of this process only, MPI untouched (a library caller, a test)
  };
  /// Joins the launcher's MPI world if there is one and `join` asks for it (MPI_Init_thread,
  /// funnelled: only the thread that joined calls MPI). Throws std::runtime_error if a
  /// launcher started this process but this build has no MPI, rather than let every rank
  /// run the whole study.
  explicit Cluster(Join join = Join::Launcher);
  /// Leaves the MPI world (MPI_Finalize) if it joined one.
  ~Cluster();
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isRoot() const { return rank_ == 0; }
  /// True when this process joined an MPI world (even a world of one, `mpirun -np 1`).
  bool joinedMpi() const { return joined_; }
  /// Rank 0's word, on every rank: rank 0 passes whether the work may go on, every rank gets
  /// it back (MPI_Bcast), so no rank waits for a study that rank 0 refused.
  bool agree(bool rootSaysGo) const;
  /// True when this build can spread work over ranks (it was built with MPI).
  static bool mpiAvailable();
  /// True when an MPI launcher (mpirun, mpiexec, srun with PMI) started this process.
  static bool launchedByMpi();

 private:
  int rank_ = 0;
  int size_ = 1;
  bool joined_ = false;
};

}  // namespace grainlab::studies
