#!/usr/bin/env bash
# The LAMMPS round trip: a small compressed disc packing exported by grainlab, run by
# Debian's LAMMPS under mpirun -np 2, its dumps imported back. Checked (compare_round_trip.py):
#  - at every frame, the contact stress grainlab computes from the dumped contacts equals
#    LAMMPS's own (compute pressure NULL pair: the pair virial over the cell's area) within
#    1e-6 of the stress's size, in a box of walls and in a periodic cell sheared by fix deform;
#  - the first frame's fabric (contacts, A_c, A_n, A_t, a_w, A_ln, A_lt, f0, l0) and stress
#    equal grainlab's own analysis of the same packing (lammps_fabric_reference) within 1e-12;
#  - the periodic cell's axial strain is fix deform's closed form, and its strain-rate
#    direction the one the deform rates give.
# The periodic run's dumps are imported gzip-compressed.
# Arguments: grainlab, lammps_fabric_reference, lmp, whether the build has MPI.
set -euo pipefail
grainlab=$1 reference=$2 lmp=$3 has_mpi=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../studies/mpi_test_env.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 "$here/packing.py" 12 12 > "$work/scene.json"
run_lammps() {  # folder
  if ! (cd "$1" && mpirun -np 2 --bind-to none "$lmp" -in in.grainlab -log log.lammps > run.out 2>&1); then
    tail -20 "$1/run.out" >&2
    echo "FAIL: LAMMPS failed on the exported $1/in.grainlab" >&2
    exit 1
  fi
  grep -q '^Loop time of .* on 2 procs' "$1/log.lammps" || { echo "FAIL: LAMMPS did not run on 2 ranks" >&2; exit 1; }
}

"$grainlab" export lammps "$work/scene.json" --out "$work/walls" --steps 300 --dump-every 30
run_lammps "$work/walls"
"$grainlab" import lammps "$work/walls/particles.dump" "$work/walls/contacts.dump" --out "$work/walls-imported"
"$reference" "$work/scene.json" > "$work/reference.txt"

# The same packing in a periodic cell, compressed along y and sheared (x stays).
"$grainlab" export lammps "$work/scene.json" --periodic --deform 0,-0.5,1 --out "$work/periodic" --steps 300 \
  --dump-every 30
run_lammps "$work/periodic"
# Imported gzip-compressed, in the other order: the reader sorts the files by their frames.
gzip "$work/periodic/particles.dump" "$work/periodic/contacts.dump"
"$grainlab" import lammps "$work/periodic/contacts.dump.gz" "$work/periodic/particles.dump.gz" \
  --out "$work/periodic-imported"

python3 "$here/compare_round_trip.py" "$work"
