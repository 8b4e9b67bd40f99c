#!/usr/bin/env bash
# A trade-off study through the API: POST /api/studies {"tradeoff": {...}} runs `grainlab
# tradeoff --seeds N`'s plan (the references first, then the settings, the paired ones on
# their seed's reference specimen), and once every run has ended its table is the CLI's
# tradeoff.csv for the same spec, every column but the three measured CPU times (which no two
# executions share). The spec is tiny: circular-quick, 2 seeds, the timestep axis (two values,
# one of them the baseline), 6 runs of a fraction of a second each. Refusals name their field
# and store nothing.
source "$(dirname "$0")/lib.sh"
cli=$GRAINLAB_CLI

start_server "$TMP_ROOT/server.log" "$TMP_ROOT/runs.db" --max-concurrent 2 --max-queued 10

refused() {  # refused DESCRIPTION FIELD BODY
  req POST /api/studies -d "$3"
  expect "$1: 400 naming $2" 400 "\"field\":\"$2\""
  req GET /api/studies
  check "...and nothing is stored" test "$(json b.studies.length)" = 0
}
refused "1 seed (an interval needs two)" tradeoff.seeds '{"tradeoff": {"seeds": 1, "quick": true}}'
refused "seeds as text" tradeoff.seeds '{"tradeoff": {"seeds": "2", "quick": true}}'
refused "no seeds" tradeoff.seeds '{"tradeoff": {"quick": true}}'
refused "an unknown axis" tradeoff.axes '{"tradeoff": {"seeds": 2, "quick": true, "axes": ["timestep"]}}'
refused "an unknown preset" 'tradeoff.presets\[1\]' '{"tradeoff": {"seeds": 2, "quick": true, "presets": ["circular-quick", "nope"]}}'
refused "no preset" tradeoff.presets '{"tradeoff": {"seeds": 2, "quick": true, "presets": []}}'
refused "an unknown key in tradeoff" tradeoff.jobs '{"tradeoff": {"seeds": 2, "jobs": 2}}'
refused "an unknown key beside tradeoff" vary '{"tradeoff": {"seeds": 2}, "vary": {}}'
refused "quick that is not a boolean" tradeoff.quick '{"tradeoff": {"seeds": 2, "quick": 1}}'
refused "more runs than the server holds (the full plan on its two presets)" tradeoff.seeds \
  '{"tradeoff": {"seeds": 2}}'

spec='{"name": "to-q2", "tradeoff": {"seeds": 2, "quick": true, "presets": ["circular-quick"], "axes": ["timestep_safety"]}}'
req POST /api/studies -d "$spec"
expect "a 2-seed quick trade-off study is launched" 201 '"name":"to-q2"'
check "...its references first: the reference setting on seeds 1 and 2" \
  test "$(json 'b.run_parameters.map(r => r.parameters.setting.split(" ")[0] + ":" + r.parameters.seed).join(" ")')" = \
  "reference:1 reference:2"
req GET /api/studies/to-q2/tradeoff
expect "no table while its runs are under way: 409" 409 '"field":"study"'

# The references, then the four others (queued as the references end): six runs.
all_done() {  # all_done [STUDY]
  for _ in $(seq 1200); do
    req GET "/api/studies/${1:-to-q2}"
    [[ $(json 'b.runs + " " + (b.by_status.completed || 0)') == "6 6" ]] && return 0
    [[ $(json 'b.by_status.failed || 0') == 0 ]] || break  # a failed run: it will not be six
    sleep 0.1
  done
  echo "study: $(json 'JSON.stringify(b.by_status)')"; return 1
}
check "all six runs complete" all_done
req GET /api/studies/to-q2
check "...the settings after the references, the 0.2 (baseline) and 0.4 timesteps on each seed" \
  test "$(json 'b.run_parameters.map(r => r.parameters.setting + ":" + r.parameters.seed).join(",")')" = \
  "reference safety 0.1, I 0.003, sample 0.005:1,reference safety 0.1, I 0.003, sample 0.005:2,timestep_safety 0.2:1,timestep_safety 0.2:2,timestep_safety 0.4:1,timestep_safety 0.4:2"
ref1=$(json 'b.run_parameters[0].id')
ref2=$(json 'b.run_parameters[1].id')
paired=$(json 'b.run_parameters[2].id + " " + b.run_parameters[5].id')
req GET "/api/runs/${paired% *}"
check "a paired run sheared seed 1's reference specimen (started from its consolidation)" \
  test "$(json 'b.started_from.run_id + " " + b.started_from.stage')" = "$ref1 consolidation"
req GET "/api/runs/${paired#* }"
check "...and seed 2's its own" test "$(json 'b.started_from.run_id')" = "$ref2"

req GET /api/studies/to-q2/tradeoff
expect "the table once every run has ended" 200 '"csv":"preset,axis,value'
check "...with one Pareto panel of three points (reference, 0.2, 0.4)" \
  test "$(json 'b.panels.length + " " + b.panels[0].points.map(p => p.label).join(",")')" = "1 reference,0.2,0.4"
FIRST=$BODY
req GET "/api/studies/to-q2/tradeoff?format=csv"
check "...as tradeoff.csv (text/csv)" grep -qi '^content-type: text/csv' "$HEADERS"
printf '%s' "$BODY" >"$TMP_ROOT/server-tradeoff.csv"

check "grainlab tradeoff on the same spec runs" "$cli" tradeoff --out "$TMP_ROOT/cli" --quick --seeds 2 \
  --presets circular-quick --axes timestep_safety --jobs 1 >/dev/null 2>&1
# Every column but the measured CPU times, byte for byte.
without_cpu() {
  python3 - "$1" <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
cost = [rows[0].index(c) for c in ("cpu_s", "cpu_s_for_tolerance", "preparation_cpu_s")]
for row in rows:
    print(",".join(("" if k in cost else cell) for k, cell in enumerate(row)))
EOF
}
same_table() {
  without_cpu "$TMP_ROOT/server-tradeoff.csv" >"$TMP_ROOT/server.cut" &&
    without_cpu "$TMP_ROOT/cli/tradeoff.csv" >"$TMP_ROOT/cli.cut" &&
    test "$(wc -l <"$TMP_ROOT/cli.cut")" -eq 43 &&
    { cmp "$TMP_ROOT/server.cut" "$TMP_ROOT/cli.cut" || { diff "$TMP_ROOT/server.cut" "$TMP_ROOT/cli.cut" | head -20; false; }; }
}
check "the server's tradeoff.csv is grainlab tradeoff's (42 rows), every column but the CPU times" same_table
check "...and the header and the row order are the CLI's, byte for byte" \
  test "$(cut -d, -f1-5 "$TMP_ROOT/server-tradeoff.csv" | md5sum)" = "$(cut -d, -f1-5 "$TMP_ROOT/cli/tradeoff.csv" | md5sum)"
positive_cpu() {
  python3 - "$TMP_ROOT/server-tradeoff.csv" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
sys.exit(0 if rows and all(float(r["cpu_s"]) > 0 for r in rows) else 1)
EOF
}
check "...its cpu_s, the server's measure of each run's CPU time, is positive on every row" positive_cpu

req GET /api/studies/to-q2/tradeoff
check "it is kept: asked again, the same answer" test "$BODY" = "$FIRST"
req GET "/api/studies/to-q2/bands?quantity=phi"
check "its bands group by setting: three groups of two seeds" \
  test "$(json 'b.group_by + " " + b.groups.map(g => g.ids.length).join("")')" = "setting 222"
# Across a restart: the same spec stopped at once, the server started again and the study
# resumed (its interrupted runs from their checkpoints or from the start). The references and
# then the other settings run, and the table is the same in every column but the CPU times.
req POST /api/studies -d "${spec/to-q2/to-again}"
expect "the same spec as another study" 201 '"name":"to-again"'
check "the server stops with it under way" stop_server
start_server "$TMP_ROOT/server2.log" "$TMP_ROOT/runs.db" --max-concurrent 2 --max-queued 10
req POST /api/studies/to-again/resume
check "...started again, the study is resumed (or had nothing to resume): $STATUS $(json "JSON.stringify(b.by_status)")" \
  test "$STATUS" = 202 -o "$STATUS" = 409
check "...and all six runs complete" all_done to-again
req GET "/api/studies/to-again/tradeoff?format=csv"
printf '%s' "$BODY" >"$TMP_ROOT/server-tradeoff.csv"
check "its tradeoff.csv is grainlab tradeoff's too, every column but the CPU times" same_table

# A busy queue when the references end: one run slot, five queue places. A long run holds the
# slot while the study is launched (its two references queue) and three tiny runs queue behind
# them; the long run is cancelled. When the second reference ends the queue has room for two
# runs, not the four settings: the study waits (rather than store two of them failed) and
# queues them once two tiny runs have ended.
check "the server stops" stop_server
start_server "$TMP_ROOT/server3.log" "$TMP_ROOT/runs.db" --max-concurrent 1 --max-queued 5
req POST /api/runs -d "$LONG_SCENE"
long=$(json b.id)
check "a long run holds the one slot" wait_status "$long" running 30
req POST /api/studies -d "${spec/to-q2/to-busy}"
expect "the study is launched behind it" 201 '"name":"to-busy"'
for k in 1 2 3; do
  req POST /api/runs -d "$TINY_SCENE"
  expect "tiny run $k queues behind the references" 201
done
req POST "/api/runs/$long/cancel"
check "all six of its runs complete, none refused for room" all_done to-busy
req GET "/api/studies/to-busy/tradeoff?format=csv"
printf '%s' "$BODY" >"$TMP_ROOT/server-tradeoff.csv"
check "...and its tradeoff.csv is grainlab tradeoff's, every column but the CPU times" same_table

req GET /api/studies/nothing/tradeoff
expect "an unknown study has no table: 404" 404
req POST /api/studies -d '{"name": "paper-q1", "paper": {"seeds": 1, "quick": true}}'
req POST /api/studies/paper-q1/cancel
req GET /api/studies/paper-q1/tradeoff
expect "a paper study has no trade-off table: 409" 409 'not a trade-off study'

check "server stops cleanly" stop_server
finish
