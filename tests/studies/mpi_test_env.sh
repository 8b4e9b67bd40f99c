# Sourced by the MPI sweep tests after `has_mpi=$2`: fails a build without MPI, and lets Open
# MPI run here. It refuses root unless told (CI and containers often run as root), and its
# shared-memory single copy needs ptrace rights a container may not grant.
case "$has_mpi" in 1|ON|TRUE|True|true|YES) ;; *)
  echo "FAIL: this build has no MPI (find_package(MPI) failed): run ./scripts/setup, which installs libopenmpi-dev" >&2
  exit 1 ;;
esac
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
