#!/usr/bin/env bash
# kill -9 of `grainlab run` (and of `grainlab resume`) at random moments, then `grainlab
# resume` until the run completes: every run must end byte-identical to the uninterrupted
# one (series.csv, final particles and contacts, summary.json apart from wall time). The
# scene checkpoints every 200 steps (checkpoint_every_s 1e-6), so a good share of the kills land
# while a checkpoint is being written; the script counts them (a `.tmp` left behind).
# Every kill of `grainlab run` must be of live work: it waits for the first checkpoint and lands
# before 80% of the uninterrupted run's wall time, and at least MIN_GENUINE of the kills must be
# genuine resumes (the process was still running when SIGKILL hit it, it left a checkpoint, and
# `grainlab resume` from it ended identical). Measured on a loaded 2-core machine the whole run
# takes about 5 s and its first checkpoint about 30 ms, so all 20 kills at 20-900 ms were genuine;
# MIN_GENUINE is 3/4 of the kills so that a run going 20% faster than the reference (load
# swings) cannot make the test flaky, while kills timed after the run ended (0 genuine) fail.
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

start_ns=$(date +%s%N)
"$grainlab" run "$work/scene.json" --out "$work/whole" 2>"$work/whole.err" || { cat "$work/whole.err"; exit 1; }
whole_ms=$((($(date +%s%N) - start_ns) / 1000000))
latest_kill_ms=$((whole_ms * 8 / 10 < 900 ? whole_ms * 8 / 10 : 900))
min_genuine=$(((kills * 3 + 3) / 4))
echo "the uninterrupted run took $whole_ms ms: kills at 20-$latest_kill_ms ms, at least $min_genuine genuine resumes required"

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

# Starts "$@", waits for its checkpoint, and kills it with SIGKILL at a random 20-latest_kill_ms
# ms after its start. Prints "live" if SIGKILL ended it (it was still running), else "ended";
# then " (during a checkpoint write)" if it was killed while a checkpoint was being written.
kill_at_random() {
  local dir=$1; shift
  local start_ns
  start_ns=$(date +%s%N)
  "$@" 2>/dev/null &
  local pid=$!
  local at_ms=$((20 + RANDOM % (latest_kill_ms - 19)))
  local t=0
  while [[ ! -e "$dir/checkpoint.bin" ]] && ((t++ < 3000)) && kill -0 "$pid" 2>/dev/null; do
    sleep 0.01
  done
  local elapsed_ms=$((($(date +%s%N) - start_ns) / 1000000))
  ((at_ms > elapsed_ms)) && sleep "$(printf '%d.%03d' $(((at_ms - elapsed_ms) / 1000)) $(((at_ms - elapsed_ms) % 1000)))"
  kill -9 "$pid" 2>/dev/null || true
  local status=0
  wait "$pid" 2>/dev/null || status=$?
  ((status == 137)) && printf live || printf ended
  [[ -e "$dir/checkpoint.bin.tmp" ]] && echo " (during a checkpoint write)" || true
}

failures=0
torn=0
genuine=0
for ((k = 1; k <= kills; ++k)); do
  dir="$work/run$k"
  note=$(kill_at_random "$dir" "$grainlab" run "$work/scene.json" --out "$dir")
  live=false; [[ $note == live* ]] && live=true
  note=${note#live}; note=${note#ended}
  had_checkpoint=false; [[ -e "$dir/checkpoint.bin" || -e "$dir/checkpoint.bin.previous" ]] && had_checkpoint=true
  [[ -n "$note" ]] && torn=$((torn + 1))
  # Every other time the resumed run is killed too.
  if ((k % 2 == 0)) && [[ -e "$dir/checkpoint.bin" ]]; then
    note2=$(kill_at_random "$dir" "$grainlab" resume "$dir")
    note2=${note2#live}; note2=${note2#ended}
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
  # Identical outputs cannot tell a resume from a fresh start (the run is deterministic): a resume
  # says the step it continued from, which must be past 0.
  if [[ $how == resumed ]] && ! grep -q '^resumed from step [1-9][0-9]* at t = ' "$work/resume.err"; then
    echo "kill $k$note: resumed, but not from its checkpoint: $(grep -m1 '^resumed from' "$work/resume.err" || echo 'no "resumed from step N" line')"
    failures=$((failures + 1))
    continue
  fi
  if verdict=$(same_outputs "$work/whole" "$dir"); then
    if [[ $how == resumed ]] && $live && $had_checkpoint; then
      genuine=$((genuine + 1))
      how="resumed from a checkpoint of the live run"
    fi
    echo "kill $k$note: $how, identical"
  else
    echo "kill $k$note: $how, $verdict"
    failures=$((failures + 1))
  fi
done
echo "$kills runs killed, $genuine genuine resumes of a live run (at least $min_genuine required), $torn kills during a checkpoint write, $failures not identical after resuming"
# For scripts/reliability's table.
echo "figure {\"section\":\"checkpoints\",\"name\":\"kill -9 of grainlab run (and of every other resume), $kills runs\",\"value\":\"$((kills - failures))/$kills identical after resuming, $genuine genuine resumes of a live run; $torn kills during a checkpoint write\",\"unit\":\"\",\"target\":\"all identical\",\"ok\":$( ((failures == 0 && genuine >= min_genuine)) && echo true || echo false)}"
((failures == 0 && genuine >= min_genuine))
