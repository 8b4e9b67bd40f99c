#!/usr/bin/env bash
# A paper study through the API: POST /api/studies {"paper": {"seeds": 1, "quick": true}}
# queues the six quick assemblies (seed 1), and once they have run the server's findings are
# `grainlab paper --quick --seeds 1`'s: its findings.csv, byte for byte. Each quick run takes
# a few seconds of CPU (the six about 30 s on one core), so the test runs the real thing.
# Refusals name their field and store nothing.
source "$(dirname "$0")/lib.sh"
cli=$GRAINLAB_CLI

start_server "$TMP_ROOT/server.log" "$TMP_ROOT/runs.db" --max-concurrent 2 --max-queued 10

# Bad input first: refused by field, nothing stored.
refused() {  # refused DESCRIPTION FIELD BODY
  req POST /api/studies -d "$3"
  expect "$1: 400 naming $2" 400 "\"field\":\"$2\""
  req GET /api/studies
  check "...and nothing is stored" test "$(json b.studies.length)" = 0
}
refused "0 seeds" paper.seeds '{"paper": {"seeds": 0, "quick": true}}'
refused "seeds that are not a whole number" paper.seeds '{"paper": {"seeds": 1.5}}'
refused "more runs than --max-queued allows (3 seeds: 18 runs, room for 12)" paper.seeds '{"paper": {"seeds": 3, "quick": true}}'
refused "an unknown key in paper" paper.sedes '{"paper": {"sedes": 1}}'
refused "an unknown key beside paper" base '{"paper": {"seeds": 1}, "base": {}}'
refused "quick that is not a boolean" paper.quick '{"paper": {"quick": "yes"}}'

req POST /api/studies -d '{"name": "paper-q1", "paper": {"seeds": 1, "quick": true}}'
expect "a 1-seed quick paper study is launched" 201 '"name":"paper-q1"'
check "...of the six assemblies, seed 1, in grainlab paper's order" \
  test "$(json 'b.run_parameters.map(r => r.parameters.preset + ":" + r.parameters.seed).join(" ")')" = \
  "circular-quick:1 elongated-random-quick:1 elongated-bedding-0-quick:1 elongated-bedding-30-quick:1 elongated-bedding-60-quick:1 elongated-bedding-90-quick:1"
ids=$(json 'b.run_parameters.map(r => r.id).join(" ")')
req GET /api/studies/paper-q1/findings
expect "no findings while its runs are under way: 409" 409 'have not ended'
for id in $ids; do check "run $id completes" wait_status "$id" completed 300; done

req GET /api/studies/paper-q1/findings
expect "the findings once every run has ended" 200 '"findings":\['
check "...all eight" test "$(json 'b.findings.map(f => f.number).join()')" = "1,2,3,4,5,6,7,8"
req GET "/api/studies/paper-q1/findings?format=csv"
SERVER_CSV=$BODY
check "...as findings.csv (text/csv)" grep -qi '^content-type: text/csv' "$HEADERS"

# The CLI on the same assemblies and seeds.
check "grainlab paper --quick --seeds 1 runs" "$cli" paper --out "$TMP_ROOT/paper" --quick --seeds 1 --jobs 1 >/dev/null 2>&1
printf '%s' "$SERVER_CSV" >"$TMP_ROOT/server-findings.csv"
same_findings() { cmp "$TMP_ROOT/server-findings.csv" "$TMP_ROOT/paper/findings.csv" || { diff "$TMP_ROOT/server-findings.csv" "$TMP_ROOT/paper/findings.csv" | head -20; return 1; }; }
check "the server's findings.csv is grainlab paper's, byte for byte" same_findings

req GET "/api/studies/paper-q1/bands?quantity=phi"
check "its bands group by preset: six groups of one run, on 201 strains to 20 %" \
  test "$(json 'b.group_by + " " + b.groups.map(g => g.ids.length).join("") + " " + b.grid.length + " " + (b.grid[200] >= 20)')" = \
  "preset 111111 201 true"
for bad in "quantity=nope quantity" "group=material.friction group" "colour=red colour"; do
  req GET "/api/studies/paper-q1/bands?${bad% *}"
  expect "bands?${bad% *}: 400 naming ${bad#* }" 400 "\"field\":\"${bad#* }\""
done

req GET /api/studies/paper-q1/findings
FIRST=$BODY
req GET /api/studies/paper-q1/findings
check "they are kept: asked again, the same answer" test "$BODY" = "$FIRST"
req GET /api/studies/nothing/findings
expect "an unknown study has none: 404" 404

check "server stops cleanly" stop_server
finish
