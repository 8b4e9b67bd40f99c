#!/usr/bin/env bash
# `grainlab sweep`: a bad spec writes nothing; the same 4-run sweep serially (--jobs 1) and
# under mpirun -np 2 and -np 3 gives the same sweep.csv (wall times aside) and byte-identical
# run outputs; deleting one run's folder and running again reruns exactly that run.
set -euo pipefail
grainlab=$1
has_mpi=${2:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

source "$(dirname "$0")/mpi_test_env.sh"

# Four short runs of circular-quick: two seeds (packings) by two frictions, sheared to 2%.
cat > "$tmp/spec.json" <<'JSON'
{ "base": { "preset": "circular-quick" },
  "vary": { "stages.2.target_axial_strain": [0.02],
            "material.friction": [0.3, 0.5],
            "seed": [1, 2] } }
JSON

# A bad spec: exit 2, one line naming the path, nothing written.
cat > "$tmp/bad.json" <<'JSON'
{ "base": { "preset": "circular-quick" }, "vary": { "material.friction": [0.3, -1] } }
JSON
if "$grainlab" sweep "$tmp/bad.json" --out "$tmp/bad" 2> "$tmp/bad.err"; then fail "a bad spec was accepted"; fi
grep -q '^error: vary.material.friction: ' "$tmp/bad.err" || fail "the error does not name the path: $(cat "$tmp/bad.err")"
[[ ! -e "$tmp/bad" ]] || fail "a bad spec wrote $tmp/bad"

"$grainlab" sweep "$tmp/spec.json" --out "$tmp/serial" --jobs 1 2> "$tmp/serial.err" || { cat "$tmp/serial.err"; fail "serial sweep"; }
grep -q '4/4 done' "$tmp/serial.err" || fail "no progress line with runs done/total"
[[ $(wc -l < "$tmp/serial/sweep.csv") -eq 5 ]] || fail "sweep.csv should have a header and 4 rows"
head -1 "$tmp/serial/sweep.csv" | grep -q '^run_id,stages.2.target_axial_strain,material.friction,seed,status,error,wall_seconds,' \
  || fail "sweep.csv header: $(head -1 "$tmp/serial/sweep.csv")"
[[ $(grep -c ',completed,' "$tmp/serial/sweep.csv") -eq 4 ]] || fail "not every run completed"

# sweep.csv without its wall_seconds column (the only one that may differ).
strip_wall() {
  python3 - "$1" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
k = rows[0].index("wall_seconds")
for r in rows: print(",".join(r[:k] + r[k+1:]))
PY
}
strip_wall "$tmp/serial/sweep.csv" > "$tmp/serial.table"
# Different packings and frictions must give different results, or the comparison proves nothing.
[[ $(cut -d, -f5- "$tmp/serial.table" | sort -u | wc -l) -eq 5 ]] || fail "the four runs' results are not distinct"

for np in 2 3; do
  mpirun -np "$np" --oversubscribe "$grainlab" sweep "$tmp/spec.json" --out "$tmp/mpi$np" 2> "$tmp/mpi$np.err" \
    || { cat "$tmp/mpi$np.err"; fail "mpirun -np $np"; }
  grep -q '(rank [12])' "$tmp/mpi$np.err" || fail "-np $np: no run went to another rank"
  strip_wall "$tmp/mpi$np/sweep.csv" > "$tmp/mpi$np.table"
  cmp "$tmp/serial.table" "$tmp/mpi$np.table" || fail "-np $np: sweep.csv differs from the serial sweep"
  for run in "$tmp"/serial/runs/*/; do
    id=$(basename "$run")
    for f in scene.json series.csv particles_final.csv contacts_final.csv; do
      cmp "$run/$f" "$tmp/mpi$np/runs/$id/$f" || fail "-np $np: $id/$f differs"
    done
  done
done

# Resume: delete one run's folder; running again reruns exactly that run and keeps the others.
victim=$(ls "$tmp/serial/runs" | sed -n 3p)
keep=$(ls "$tmp/serial/runs" | sed -n 1p)
before=$(stat -c %Y.%y "$tmp/serial/runs/$keep/series.csv")
cp "$tmp/serial/runs/$victim/series.csv" "$tmp/victim-series.csv"
rm -rf "$tmp/serial/runs/$victim"
"$grainlab" sweep "$tmp/spec.json" --out "$tmp/serial" --jobs 2 2> "$tmp/resume.err" || { cat "$tmp/resume.err"; fail "resume"; }
grep -q '3 already completed (kept), 1 to run' "$tmp/resume.err" || fail "resume did not rerun exactly one: $(head -1 "$tmp/resume.err")"
grep -q "started $victim" "$tmp/resume.err" || fail "resume ran something other than $victim"
[[ $(stat -c %Y.%y "$tmp/serial/runs/$keep/series.csv") == "$before" ]] || fail "resume rewrote a completed run"
cmp "$tmp/victim-series.csv" "$tmp/serial/runs/$victim/series.csv" || fail "the rerun differs from the first run"
strip_wall "$tmp/serial/sweep.csv" | cmp - "$tmp/serial.table" || fail "sweep.csv changed after the resume"

# Resuming with another spec is refused, and nothing is touched.
sed 's/0.3, 0.5/0.3, 0.6/' "$tmp/spec.json" > "$tmp/other.json"
if "$grainlab" sweep "$tmp/other.json" --out "$tmp/serial" 2> "$tmp/other.err"; then fail "another spec resumed this sweep"; fi
grep -q '^error: --out: ' "$tmp/other.err" || fail "refusal does not name --out: $(cat "$tmp/other.err")"
echo "sweep_mpi: serial, -np 2 and -np 3 agree bit for bit; resume reran exactly $victim"
