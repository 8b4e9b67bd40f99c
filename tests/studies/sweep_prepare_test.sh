#!/usr/bin/env bash
# `grainlab sweep` with "prepare": 2 seeds x 2 strain rates on circular-quick make 2
# preparations and 4 tests; the test at the base's own strain rate writes, from the prepared
# stage's last row on, the same series.csv bytes as the same seed's run in a sweep without
# "prepare"; the same spec under mpirun -np 2 writes the serial sweep's bytes; running it
# again runs nothing; a spec varying what the preparation depends on is refused by that path.
set -euo pipefail
grainlab=$1
has_mpi=${2:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

source "$(dirname "$0")/mpi_test_env.sh"

# The preset shears at strain_rate 1.0: the first rate is its own, the second another.
cat > "$tmp/prepared.json" <<'JSON'
{ "base": { "preset": "circular-quick" },
  "prepare": { "stage": "consolidation" },
  "vary": { "stages.2.target_axial_strain": [0.02],
            "seed": [1, 2],
            "stages.2.strain_rate": [1.0, 3.0] } }
JSON
cat > "$tmp/plain.json" <<'JSON'
{ "base": { "preset": "circular-quick" },
  "vary": { "stages.2.target_axial_strain": [0.02],
            "seed": [1, 2] } }
JSON

"$grainlab" sweep "$tmp/prepared.json" --out "$tmp/serial" --jobs 1 2> "$tmp/serial.err" || { cat "$tmp/serial.err"; fail "serial sweep"; }
[[ $(ls "$tmp/serial/specimens") == $'seed-1\nseed-2' ]] || fail "specimens: $(ls "$tmp/serial/specimens")"
grep -q '^\[prepare\] 2/2 done' "$tmp/serial.err" || fail "no line saying the 2 preparations were done"
grep -q '^\[sweep\] 4/4 done' "$tmp/serial.err" || fail "no line saying the 4 tests were done"
[[ $(grep -c ',completed,' "$tmp/serial/sweep.csv") -eq 4 ]] || fail "not every test completed: $(cat "$tmp/serial/sweep.csv")"
head -1 "$tmp/serial/sweep.csv" | grep -q '^run_id,stages.2.target_axial_strain,seed,stages.2.strain_rate,specimen,status,' \
  || fail "sweep.csv header: $(head -1 "$tmp/serial/sweep.csv")"
grep -q '^003-[^,]*,0.02,2,1.0,specimens/seed-2,completed,' "$tmp/serial/sweep.csv" || fail "run 003's specimen: $(cat "$tmp/serial/sweep.csv")"
for s in 1 2; do  # a preparation stops after its stage: no shearing rows
  [[ -f "$tmp/serial/specimens/seed-$s/stages/consolidation.checkpoint" ]] || fail "seed $s: no specimen"
  grep -q ',shearing,' "$tmp/serial/specimens/seed-$s/series.csv" && fail "seed $s's preparation sheared"
done

"$grainlab" sweep "$tmp/plain.json" --out "$tmp/plain" --jobs 1 2> "$tmp/plain.err" || { cat "$tmp/plain.err"; fail "plain sweep"; }
# Tests at rate 1.0: seed 1 is run 001, seed 2 run 003; the plain sweep's are 001 and 002.
for pair in "001 001 1" "003 002 2"; do
  read -r test plain seed <<< "$pair"
  t=$(ls -d "$tmp/serial/runs/$test"-*) p=$(ls -d "$tmp/plain/runs/$plain"-*)
  first=$(sed -n 2p "$t/series.csv")
  [[ "$first" == "$(tail -1 "$tmp/serial/specimens/seed-$seed/series.csv")" ]] || fail "$test: does not begin with its specimen's last row"
  from=$(grep -nxF "$first" "$p/series.csv" | cut -d: -f1)
  [[ -n "$from" ]] || fail "$test: its first row is not a row of the plain run"
  [[ $(grep -c ',consolidation,' "$t/series.csv") -eq 1 ]] || fail "$test: ran more of the preparation than its last row"
  { head -1 "$p/series.csv"; tail -n +"$from" "$p/series.csv"; } | cmp - "$t/series.csv" || fail "$test: series differs from the plain run of seed $seed"
  for f in particles_final.csv contacts_final.csv; do cmp "$t/$f" "$p/$f" || fail "$test: $f differs from the plain run"; done
done
# The other rate must give other results, or the sweep varied nothing.
cmp -s "$(ls -d "$tmp/serial/runs/001"-*)/series.csv" "$(ls -d "$tmp/serial/runs/002"-*)/series.csv" && fail "rates 1.0 and 3.0 gave the same series"

mpirun -np 2 --oversubscribe "$grainlab" sweep "$tmp/prepared.json" --out "$tmp/mpi" 2> "$tmp/mpi.err" || { cat "$tmp/mpi.err"; fail "mpirun -np 2"; }
for run in "$tmp"/serial/runs/*/ "$tmp"/serial/specimens/*/; do
  rel=${run#"$tmp/serial/"}
  for f in series.csv particles_final.csv contacts_final.csv; do
    cmp "$run/$f" "$tmp/mpi/$rel/$f" || fail "-np 2: $rel$f differs from the serial sweep"
  done
done

# Again: nothing to prepare, nothing to run.
"$grainlab" sweep "$tmp/prepared.json" --out "$tmp/serial" --jobs 1 2> "$tmp/again.err" || { cat "$tmp/again.err"; fail "resume"; }
grep -q '^\[prepare\].*2 already completed (kept), 0 to run' "$tmp/again.err" || fail "resume prepared again: $(cat "$tmp/again.err")"
grep -q '^\[sweep\].*4 already completed (kept), 0 to run' "$tmp/again.err" || fail "resume ran again: $(cat "$tmp/again.err")"

# Varying what the preparation depends on is refused by that path, and nothing is written.
refused() {  # spec-vary expected-field
  printf '{ "base": { "preset": "circular-quick" }, "prepare": {"stage": "consolidation"}, "vary": %s }\n' "$1" > "$tmp/bad.json"
  if "$grainlab" sweep "$tmp/bad.json" --out "$tmp/bad" 2> "$tmp/bad.err"; then fail "accepted $1"; fi
  grep -q "^error: $2: " "$tmp/bad.err" || fail "$1: the error does not name $2: $(cat "$tmp/bad.err")"
  [[ ! -e "$tmp/bad" ]] || fail "$1: a refused spec wrote $tmp/bad"
}
refused '{"seed": [1, 2], "material.friction": [0.3, 0.5]}' 'vary.material.friction'
refused '{"stages.1.pressure": [1e5, 3e5]}' 'vary.stages.1.pressure'
refused '{"solver.engine": ["dem", "box2d"]}' 'vary.solver.engine'
refused '{"assembly.disc_radius": [0.002, 0.0025]}' 'vary.assembly.disc_radius'
echo "sweep_prepare: 2 preparations, 4 tests; equal to the plain sweep from the specimen on; -np 2 equal to serial"
