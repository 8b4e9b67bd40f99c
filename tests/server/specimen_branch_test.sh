#!/usr/bin/env bash
# A new test on a stored run's specimen (docs/prepared-specimens.md, docs/http-api.md):
# POST /api/runs with "start_from": {"run_id": N, "stage": S} starts from the end of stage S
# that run N kept in the server's own storage. Exact: the same scene's shearing stage on run
# N's consolidated specimen stores run N's rows byte for byte. The run records where it
# started; every bad start_from is refused naming its field, and a file path in start_from
# stays refused: the server reads no file a request names.
source "$(dirname "$0")/lib.sh"

DB=$TMP_ROOT/data/branch.db
CHECKPOINTS=$DB.checkpoints
# circular-quick sheared to 2 % (a few seconds): consolidated specimen, ring, servo and
# tangential springs are all carried over.
SCENE=$("$GRAINLAB_CLI" preset circular-quick | node -e '
  const s = JSON.parse(require("fs").readFileSync(0, "utf8"));
  s.name = "parent"; s.stages[2].target_axial_strain = 0.02;
  console.log(JSON.stringify(s));')
# with(JS): the scene changed by a JavaScript statement on `s`.
with() { node -e "const s = JSON.parse(process.argv[1]); $1; console.log(JSON.stringify(s))" "$SCENE"; }

start_server "$TMP_ROOT/server.log" "$DB" --max-concurrent 1

req POST /api/runs --data "$SCENE"
expect "the parent run is accepted" 201
PARENT=$(json b.id)
check "the parent completes" wait_status "$PARENT" completed 180
req GET "/api/runs/$PARENT"
check "it kept its three stages' ends ($(json 'JSON.stringify(b.specimen_stages)'))" \
  test "$(json 'b.specimen_stages.join()')" = "compaction,consolidation,shearing"
check "it started from nothing" test "$(json b.started_from)" = null
PARENT_STEPS=$(json b.steps)
check "its stage checkpoints are in the server's storage" test -f "$CHECKPOINTS/run-$PARENT/stages/consolidation.checkpoint"

# ---- the exact branch: the parent's own shearing on its consolidated specimen ----
req POST /api/runs --data "$(with "s.name = 'child'; s.start_from = {run_id: $PARENT, stage: 'consolidation'}")"
expect "a run starting from the parent's consolidation is accepted" 201
CHILD=$(json b.id)
check "the child completes" wait_status "$CHILD" completed 180
req GET "/api/runs/$CHILD"
check "the child records its origin ($(json 'JSON.stringify(b.started_from)'))" \
  test "$(json 'JSON.stringify(b.started_from)')" = "{\"run_id\":$PARENT,\"stage\":\"consolidation\"}"
check "its clock went on from the parent's: it ends at the parent's last step ($PARENT_STEPS)" test "$(json b.steps)" = "$PARENT_STEPS"
check "it estimated only its own stage (shearing to 2 %)" node -e "process.exit($(json b.estimated_seconds) < 60 ? 0 : 1)"
req GET "/api/runs/$PARENT/series?format=csv"
# The parent's rows from its last consolidation row on: where the specimen was kept.
printf '%s' "$BODY" | awk -F, 'NR == 1 { print; next } { rows[NR] = $0; stage[NR] = $3 }
  END { for (k = 2; k <= NR; k++) if (stage[k] == "consolidation") last = k; for (k = last; k <= NR; k++) print rows[k] }' \
  >"$TMP_ROOT/parent-from-consolidation.csv"
req GET "/api/runs/$CHILD/series?format=csv"
printf '%s' "$BODY" >"$TMP_ROOT/child.csv"
PARENT_ROWS=$(($(wc -l <"$TMP_ROOT/parent-from-consolidation.csv") - 1))
check "the parent sheared ($PARENT_ROWS rows from the end of consolidation on)" test "$PARENT_ROWS" -ge 5
check "the child's series is the parent's from the end of consolidation on, byte for byte" \
  cmp "$TMP_ROOT/parent-from-consolidation.csv" "$TMP_ROOT/child.csv"

# ---- another test on the same specimen: shearing twice as fast ----
req POST /api/runs --data "$(with "s.name = 'fast'; s.stages[2].strain_rate *= 2; s.start_from = {run_id: $PARENT}")"
expect "without a stage it starts before the first shearing stage" 201
FAST=$(json b.id)
check "the faster test completes" wait_status "$FAST" completed 180
req GET "/api/runs/$FAST"
check "the stage it started from is recorded" test "$(json b.started_from.stage)" = consolidation
req GET "/api/runs/$FAST/series?format=csv"
printf '%s' "$BODY" >"$TMP_ROOT/fast.csv"
check "its first row is the parent's consolidated specimen" \
  test "$(sed -n 2p "$TMP_ROOT/fast.csv")" = "$(sed -n 2p "$TMP_ROOT/parent-from-consolidation.csv")"
check "and its shearing differs from the parent's (another rate)" \
  test "$(sed -n 4p "$TMP_ROOT/fast.csv")" != "$(sed -n 4p "$TMP_ROOT/parent-from-consolidation.csv")"

# ---- refusals, each naming its field ----
refused() {  # refused DESCRIPTION STATUS FIELD PATTERN BODY
  req POST /api/runs --data "$5"
  expect "$1" "$2" "\"field\":\"$3\""
  grep -qE -- "$4" <<<"$BODY" || fail "$1: the message does not say /$4/: $BODY"
  [[ $BODY != *"$CHECKPOINTS"* ]] || fail "$1: the answer names the server's storage: $BODY"
}
refused "a run directory on the server's disk is refused" 400 start_from.run "reads no file a request names" \
  "$(with "s.start_from = {run: '$CHECKPOINTS/run-$PARENT', stage: 'consolidation'}")"
refused "a checkpoint file on the server's disk is refused" 400 start_from.checkpoint "reads no file a request names" \
  "$(with "s.start_from = {checkpoint: '$CHECKPOINTS/run-$PARENT/stages/consolidation.checkpoint'}")"
refused "an unknown run" 400 start_from.run_id "no run 999999" "$(with "s.start_from = {run_id: 999999}")"
refused "a run id that is not a number" 400 start_from.run_id "integer" "$(with "s.start_from = {run_id: '$PARENT'}")"
refused "run_id 0" 400 start_from.run_id "between 1 and" "$(with "s.start_from = {run_id: 0}")"
refused "run_id with a path" 400 start_from "give one of" "$(with "s.start_from = {run_id: $PARENT, run: '/tmp'}")"
refused "a stage the run does not have" 400 start_from.stage "has no stage 'settling'" \
  "$(with "s.start_from = {run_id: $PARENT, stage: 'settling'}")"
refused "a stage name that tries to leave the run's folder" 400 start_from.stage "has no stage" \
  "$(with "s.start_from = {run_id: $PARENT, stage: '../../run-$PARENT/stages/consolidation'}")"
refused "another assembly (particle count)" 400 start_from.run_id "the specimen has [0-9]+ particles, this scene's assembly makes" \
  "$(with "s.assembly.particle_count = 100; s.start_from = {run_id: $PARENT}")"
refused "another seed" 400 start_from.run_id "seed" "$(with "s.seed = 99; s.start_from = {run_id: $PARENT}")"
refused "another engine" 400 start_from.run_id 'solver.engine \\"dem\\"' \
  "$(with "s.solver.engine = 'box2d'; s.start_from = {run_id: $PARENT}")"
refused "a scene with nothing to run after the stage" 400 start_from.stage "no stage after 'shearing'" \
  "$(with "s.start_from = {run_id: $PARENT, stage: 'shearing'}")"
req GET /api/runs
check "nothing was stored for the refused requests (3 runs)" test "$(json b.runs.length)" = 3
check "nothing was left in the checkpoint directory" test -z "$(ls "$CHECKPOINTS" | grep -v '^run-')"

# ---- a run that has not ended the stage yet, and one that never will ----
req POST /api/runs --data "$(with "s.name = 'slow'; s.stages[0].strain_rate = 0.01; s.stages[0].max_time = 1000")"
SLOW=$(json b.id)
check "a slow parent is running" wait_status "$SLOW" running 30
refused "its consolidation has not ended: 409" 409 start_from.run_id "has not ended stage 'consolidation' yet" \
  "$(with "s.start_from = {run_id: $SLOW}")"
req POST "/api/runs/$SLOW/cancel"
check "cancelled" wait_status "$SLOW" cancelled 60
refused "once cancelled it never will: 400" 400 start_from.run_id "kept no checkpoint of stage 'consolidation'.*ended cancelled" \
  "$(with "s.start_from = {run_id: $SLOW}")"

# ---- the child stands on its own: its parent deleted, a grandchild from the child ----
req DELETE "/api/runs/$PARENT"
expect "the parent is deleted" 204
check "with its stages' ends" test ! -e "$CHECKPOINTS/run-$PARENT"
req GET "/api/runs/$CHILD"
check "the child still offers the specimen it started from ($(json 'JSON.stringify(b.specimen_stages)'))" \
  test "$(json 'b.specimen_stages.join()')" = "consolidation,shearing"
req POST /api/runs --data "$(with "s.name = 'grandchild'; s.start_from = {run_id: $CHILD, stage: 'consolidation'}")"
expect "a test on the child's specimen, after its parent was deleted" 201
GRANDCHILD=$(json b.id)
check "it completes" wait_status "$GRANDCHILD" completed 180
req GET "/api/runs/$GRANDCHILD/series?format=csv"
printf '%s' "$BODY" >"$TMP_ROOT/grandchild.csv"
check "its series is the child's, byte for byte" cmp "$TMP_ROOT/child.csv" "$TMP_ROOT/grandchild.csv"

# ---- a queued child survives a restart with its own copy of the specimen ----
req POST /api/runs --data "$(with "s.name = 'blocker'; s.stages[0].strain_rate = 0.01; s.stages[0].max_time = 1000")"
BLOCKER=$(json b.id)
check "a long run holds the only slot" wait_status "$BLOCKER" running 30
req POST /api/runs --data "$(with "s.name = 'waiting'; s.start_from = {run_id: $CHILD, stage: 'consolidation'}")"
WAITING=$(json b.id)
req GET "/api/runs/$WAITING"
check "the test on the specimen waits in the queue" test "$(json b.status)" = queued
check "the server stops cleanly" stop_server TERM
start_server "$TMP_ROOT/server2.log" "$DB" --max-concurrent 1
check "after the restart the waiting test runs and completes" wait_status "$WAITING" completed 180
req GET "/api/runs/$WAITING/series?format=csv"
printf '%s' "$BODY" >"$TMP_ROOT/waiting.csv"
check "with the same rows" cmp "$TMP_ROOT/child.csv" "$TMP_ROOT/waiting.csv"
req GET /api/health
check "schema version 5 or later (5 added the origin columns)" test "$(json b.schema_version)" -ge 5

stop_server
finish
