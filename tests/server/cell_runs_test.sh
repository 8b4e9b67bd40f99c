#!/usr/bin/env bash
# Periodic cell runs through the server: a two-seed sweep of the quick periodic biaxial preset
# (shearing cut to 0.5 % strain, its specimens prepared once per seed) imported with
# `grainlab import` and POST /api/sweeps/import, its series served byte for byte as the runs'
# series.csv, and one seed of it launched by the server as a study (POST /api/studies) with
# the same peak φ_mob; and a cell scene posted to the API whose stored frames carry the cell's edges
# after a 56-byte header (docs/stream-protocol.md), where a ring run's frames keep the 40 bytes.
source "$(dirname "$0")/lib.sh"
cli=$GRAINLAB_CLI

# The quick periodic preset in the quick ring's smaller cell (0.06 m, 177 discs): enough for the
# plumbing, and a third of the preset's cost.
base=$("$cli" preset periodic-biaxial-circular-quick | node -e "
  const s = JSON.parse(require('fs').readFileSync(0, 'utf8'));
  s.assembly.specimen_diameter = 0.06;
  console.log(JSON.stringify(s))")
cat > "$TMP_ROOT/cells.json" <<JSON
{ "name": "cells", "base": $base,
  "vary": { "seed": [1, 2], "stages.2.target_axial_strain": [0.005] }, "prepare": {} }
JSON
"$cli" sweep "$TMP_ROOT/cells.json" --out "$TMP_ROOT/cells" --jobs 2 >"$TMP_ROOT/sweep.log" 2>&1
check "a two-seed sweep of a periodic preset completes" grep -q '2 of 2 runs completed' "$TMP_ROOT/sweep.log"
check "...each run in its own cell specimen, 177 discs, consolidated (void ratio in the table)" \
  test "$(node -e "
    const rows = require('fs').readFileSync('$TMP_ROOT/cells/sweep.csv', 'utf8').trim().split('\n').map((l) => l.split(','));
    const h = rows[0], at = (r, k) => r[h.indexOf(k)];
    console.log(rows.slice(1).map((r) => at(r, 'status') + ':' + at(r, 'particles') + ':' + (Number(at(r, 'void_ratio_after_consolidation')) > 0)).join(' '))")" \
  = "completed:177:true completed:177:true"

db=$TMP_ROOT/runs.db
out=$("$cli" import "$TMP_ROOT/cells" --db "$db")
check "grainlab import adds both cell runs" grep -q '^imported 2 runs' <<<"$out"
start_server "$TMP_ROOT/server.log" "$db" --import-root "$TMP_ROOT"
req GET "/api/runs?study=cells"
expect "the server lists the imported cell runs as the study cells" 200 '"study":"cells"'
id=$(json 'b.runs.find(r => r.name.startsWith("cells/002")).id')
req GET "/api/runs/$id/series?format=csv"
check "an imported cell run's series is its series.csv byte for byte" \
  cmp <(printf '%s' "$BODY") "$TMP_ROOT/cells/runs/002-seed=2-target_axial_strain=0.005/series.csv"
req POST /api/sweeps/import -H 'Content-Type: application/json' -d "{\"dir\": \"$TMP_ROOT/cells\"}"
expect "POST /api/sweeps/import of the same sweep finds both there" 200 '"already_there":2'

# The same cell run launched by the server as a study: the same peak φ_mob, to the bit.
req POST /api/studies -d "{\"name\": \"cellstudy\", \"base\": $base,
  \"vary\": {\"seed\": [2], \"stages.2.target_axial_strain\": [0.005]}}"
expect "POST /api/studies launches a study of a periodic preset" 201 '"name":"cellstudy"'
for _ in $(seq 600); do
  req GET /api/studies/cellstudy
  [[ $(json b.status) == completed || $(json b.status) == failed ]] && break
  sleep 0.1
done
expect "...which completes" 200 '"status":"completed"'
req GET "/api/runs?study=cellstudy"
check "...with the sweep's peak phi_mob for seed 2, bit for bit" test "$(node -e "
  const rows = require('fs').readFileSync('$TMP_ROOT/cells/sweep.csv', 'utf8').trim().split('\n').map((l) => l.split(','));
  const h = rows[0], sweep = Number(rows[2][h.indexOf('peak_phi_mob_deg')]);
  const b = JSON.parse(process.argv[1]);
  console.log(b.runs[0].peak_phi_mob_deg === sweep && sweep > 0)" "$BODY")" = true

# A cell of explicit particles through POST /api/runs, and its stored frames.
cell='{"name":"cell","particles":[{"shape":"disc","radius":0.002,"position":[0.0005,0.005]},{"shape":"disc","radius":0.002,"position":[0.01,0.01]}],"boundary":{"type":"periodic","size":[0.02,0.015]},"stages":[{"type":"free","duration":0.002}],"output":{"sample_interval":0.0005}}'
req POST /api/runs -d "$cell"
expect "a cell scene is accepted by the API" 201
cid=$(json b.id)
wait_status "$cid" completed 60 && pass "the cell run completes" || fail "the cell run completes"
req GET "/api/runs/$cid/frames"
last=$(json 'b.frames[b.frames.length - 1].index')
curl -s "$(BASE)/api/runs/$cid/frames?index=$last" -o "$TMP_ROOT/frame.bin"
check "its frame states a 56-byte header and carries h1 = (0.02, 0), h2 = (0, 0.015)" test "$(node -e "
  const b = require('fs').readFileSync('$TMP_ROOT/frame.bin');
  console.log([b.readUInt16LE(6), ...[40, 44, 48, 52].map((o) => b.readFloatLE(o).toPrecision(6))].join(' '))")" \
  = "56 0.0200000 0.00000 0.00000 0.0150000"
req POST /api/runs -d "$TINY_SCENE"
tid=$(json b.id)
wait_status "$tid" completed 60
req GET "/api/runs/$tid/frames"
curl -s "$(BASE)/api/runs/$tid/frames?index=$(json 'b.frames[0].index')" -o "$TMP_ROOT/ring.bin"
check "a run without a cell keeps version 1's 40-byte header" \
  test "$(node -e "console.log(require('fs').readFileSync('$TMP_ROOT/ring.bin').readUInt16LE(6))")" = 40
stop_server
finish
