#include "grainlab/studies/cluster.hpp"

#include <cstdlib>
#include <stdexcept>

#ifdef GRAINLAB_HAS_MPI
#include <mpi.h>
#endif

namespace grainlab::studies {

bool Cluster::mpiAvailable() {
#ifdef GRAINLAB_HAS_MPI
  return true;
#else
  return false;
#endif
}

bool Cluster::launchedByMpi() {
  // Open MPI's mpirun, MPICH/Hydra and Slurm's PMI2, and PMIx (srun --mpi=pmix) each set one.
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

Cluster::Cluster(Join join) {
  if (join == Join::Alone || !launchedByMpi()) return;
#ifdef GRAINLAB_HAS_MPI
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  joined_ = true;
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    joined_ = false;
    throw std::runtime_error("this MPI library cannot run threads beside MPI (MPI_THREAD_FUNNELED)");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
  throw std::runtime_error(
      "started by an MPI launcher, but this grainlab was built without MPI: install libopenmpi-dev "
      "(./scripts/setup does) and rebuild, or run without mpirun");
#endif
}

bool Cluster::agree(bool rootSaysGo) const {
#ifdef GRAINLAB_HAS_MPI
  if (joined_ && size_ > 1) {
    int go = rootSaysGo ? 1 : 0;
    MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return go != 0;
  }
#endif
  return rootSaysGo;
}

Cluster::~Cluster() {
#ifdef GRAINLAB_HAS_MPI
  if (joined_) MPI_Finalize();
#endif
}

}  // namespace grainlab::studies
