#!/usr/bin/env bash
# kill -9 of `grainlab run` (and of `grainlab resume`) at random moments, then `grainlab
# resume` until the run completes: every run must end byte-identical to the uninterrupted
# one (series.csv, final particles and contacts, summary.json apart from wall time). The
# scene checkpoints every 200 steps (checkpoint_every_s 1e-6), so a good share of the kills land
# while a checkpoint is being written; the script counts them (a `.tmp` left behind).
#
# usage: resume_kill_test.sh GRAINLAB [KILLS=20] [SEED]   (prints one line per kill)
set -euo pipefail
grainlab=$1
kills=${2:-20}
RANDOM=${3:-$$}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$grainlab" preset circular-quick | python3 -c '
import json, sys
s = json.load(sys.stdin)
s["output"]["checkpoint_every_s"] = 1e-6
json.dump(s, sys.stdout)' >"$work/scene.json"

"$grainlab" run "$work/scene.json" --out "$work/whole" 2>"$work/whole.err" || { cat "$work/whole.err"; exit 1; }

same_outputs() {  # $1 $2: run directories
  local f
  for f in series.csv particles_final.csv contacts_final.csv histograms.csv; do
    cmp -s "$1/$f" "$2/$f" || { echo "$f differs"; return 1; }
  done
  python3 - "$1/summary.json" "$2/summary.json" <<'EOF'
import json, sys
def deterministic(path):
    s = json.load(open(path))
    for key in ("wall_seconds", "sample_seconds", "particle_steps_per_second", "checkpoints"):
        s.pop(key, None)
    for key in ("forces", "integrate", "neighbors"):
        s.get("profile_seconds", {}).pop(key, None)
    s.get("stage_checkpoints", {}).pop("seconds", None)  # wall time spent writing them
    return s
a, b = (deterministic(p) for p in sys.argv[1:])
if a != b:
    print("summary.json differs:", {k: (a.get(k), b.get(k)) for k in set(a) | set(b) if a.get(k) != b.get(k)})
    sys.exit(1)
EOF
}

# Starts "$@" and kills it with SIGKILL after a random 20-900 ms; says whether it was killed
# while a checkpoint was being written.
kill_at_random() {
  local dir=$1; shift
  "$@" 2>/dev/null &
  local pid=$!
  sleep "0.$(printf %03d $((20 + RANDOM % 880)))"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  [[ -e "$dir/checkpoint.bin.tmp" ]] && echo " (during a checkpoint write)" || true
}

failures=0
torn=0
for ((k = 1; k <= kills; ++k)); do
  dir="$work/run$k"
  note=$(kill_at_random "$dir" "$grainlab" run "$work/scene.json" --out "$dir")
  [[ -n "$note" ]] && torn=$((torn + 1))
  # Every other time the resumed run is killed too.
  if ((k % 2 == 0)) && [[ -e "$dir/checkpoint.bin" ]]; then
    note2=$(kill_at_random "$dir" "$grainlab" resume "$dir")
    [[ -n "$note2" ]] && torn=$((torn + 1))
    note+="; resume killed$note2"
  fi
  if [[ -e "$dir/checkpoint.bin" || -e "$dir/checkpoint.bin.previous" ]]; then
    if ! "$grainlab" resume "$dir" 2>"$work/resume.err"; then
      echo "kill $k: resume failed: $(tail -3 "$work/resume.err")"
      failures=$((failures + 1))
      continue
    fi
    how=resumed
  elif [[ -e "$dir/summary.json" ]] && grep -q '"completed"' "$dir/summary.json"; then
    how="finished before the kill"
  else
    "$grainlab" run "$work/scene.json" --out "$dir" 2>/dev/null  # killed before its first checkpoint
    how="restarted (no checkpoint yet)"
  fi
  if verdict=$(same_outputs "$work/whole" "$dir"); then
    echo "kill $k$note: $how, identical"
  else
    echo "kill $k$note: $how, $verdict"
    failures=$((failures + 1))
  fi
done
echo "$kills runs killed, $torn kills during a checkpoint write, $failures not identical after resuming"
# For scripts/reliability's table.
echo "figure {\"section\":\"checkpoints\",\"name\":\"kill -9 of grainlab run (and of every other resume), $kills runs\",\"value\":\"$((kills - failures))/$kills identical after resuming; $torn kills during a checkpoint write\",\"unit\":\"\",\"target\":\"all identical\",\"ok\":$( ((failures == 0)) && echo true || echo false)}"
((failures == 0))
