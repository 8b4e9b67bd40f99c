#!/usr/bin/env bash
# An imported sweep is a study as a launched one is: POST /api/sweeps/import of a `grainlab
# sweep` folder (circular-quick sheared to 5 %, friction 0.3 and 0.5 by seeds 1 and 2: four
# runs of about a second) stores a studies row with the sweep's spec and each run's values, so
# its bands group by friction: two groups of two runs, each group exactly the runs sweep.csv
# gives that friction, and each group's mean of φ_mob at its last common strain the mean of its
# runs' own series.csv in the sweep folder there. Before schema 10 the import stored no row and
# the bands had one group of four. Importing again keeps one row; a launched study's name is
# not taken over.
source "$(dirname "$0")/lib.sh"
cli=$GRAINLAB_CLI

cat >"$TMP_ROOT/spec.json" <<'JSON'
{ "name": "friction-2x2", "base": { "preset": "circular-quick" },
  "vary": { "material.friction": [0.3, 0.5], "stages.2.target_axial_strain": [0.05], "seed": [1, 2] } }
JSON
check "grainlab sweep runs the 2 x 2 sweep" "$cli" sweep "$TMP_ROOT/spec.json" --out "$TMP_ROOT/sweep" --jobs 1

start_server "$TMP_ROOT/server.log" "$TMP_ROOT/runs.db" --import-root "$TMP_ROOT"
req POST /api/sweeps/import -d "{\"dir\": \"$TMP_ROOT/sweep\"}"
expect "POST /api/sweeps/import adds its four runs" 200 '"imported":4'
req GET /api/studies/friction-2x2
expect "the sweep is a study" 200 '"source":"imported"'
check "...with the sweep's spec, its vary in the sweep's order" \
  test "$(json 'Object.keys(b.spec.vary).join(",")')" = "material.friction,stages.2.target_axial_strain,seed"
check "...and each run's values" \
  test "$(json 'b.run_parameters.map(r => r.parameters["material.friction"] + ":" + r.parameters.seed).join(" ")')" = \
  "0.3:1 0.3:2 0.5:1 0.5:2"

req GET "/api/studies/friction-2x2/bands?quantity=phi"
expect "its bands" 200 '"group_by":"material.friction"'
printf '%s' "$BODY" >"$TMP_ROOT/bands.json"
req GET /api/runs?study=friction-2x2
printf '%s' "$BODY" >"$TMP_ROOT/runs.json"
same_as_sweep() {
  node - "$TMP_ROOT" <<'EOF'
const fs = require('fs');
const dir = process.argv[2];
const bands = JSON.parse(fs.readFileSync(`${dir}/bands.json`, 'utf8'));
const runs = JSON.parse(fs.readFileSync(`${dir}/runs.json`, 'utf8')).runs;
const table = fs.readFileSync(`${dir}/sweep/sweep.csv`, 'utf8').trim().split('\n').map((l) => l.split(','));
const friction = (id) => table.find((row) => row[0] === id)[table[0].indexOf('material.friction')];
// φ_mob at `strain` (%) from a run's series.csv, interpolated linearly in its shearing stage.
const phiAt = (runId, strain) => {
  const [header, ...lines] = fs.readFileSync(`${dir}/sweep/runs/${runId}/series.csv`, 'utf8').trim().split('\n');
  const c = (name) => header.split(',').indexOf(name);
  const rows = lines.map((l) => l.split(',')).filter((r) => r[c('stage')] === 'shearing');
  const xs = rows.map((r) => Number(r[c('axial_strain')]) * 100), ys = rows.map((r) => Number(r[c('phi_mob_deg')]));
  const k = xs.findIndex((x) => x >= strain - 1e-9 * Math.abs(strain));
  return xs[k] === strain || k === 0 ? ys[k] : ys[k - 1] + (strain - xs[k - 1]) / (xs[k] - xs[k - 1]) * (ys[k] - ys[k - 1]);
};
let ok = bands.groups.length === 2;
console.log(`${bands.groups.length} groups: ${bands.groups.map((g) => `${g.value} (${g.ids.length} runs)`).join(', ')}`);
for (const g of ok ? bands.groups : []) {
  const ids = g.ids.map((id) => runs.find((r) => r.id === id).name.split('/')[1]);
  const inTable = table.slice(1).filter((row) => friction(row[0]) === g.value).map((row) => row[0]);
  // The last strain every run of the group reaches, and the band's mean there.
  let i = bands.grid.length - 1;
  while (i > 0 && !(g.n[i] === g.ids.length && g.mean[i] !== null)) i--;
  const own = ids.map((id) => phiAt(id, bands.grid[i]));
  const mean = own.reduce((a, b) => a + b, 0) / own.length;
  const same = ids.length === 2 && ids.join() === inTable.join() && Math.abs(g.mean[i] - mean) <= 1e-9 * Math.abs(mean);
  console.log(`friction ${g.value}: runs ${ids} (sweep.csv: ${inTable}), mean at ${bands.grid[i]} %: ${g.mean[i]} (series: ${mean})`);
  ok = ok && same;
}
process.exit(ok ? 0 : 1);
EOF
}
check "two groups, one per friction, each the sweep's runs of it and the mean of their series" same_as_sweep

req POST /api/sweeps/import -d "{\"dir\": \"$TMP_ROOT/sweep\"}"
expect "importing again adds no run" 200 '"already_there":4'
req GET /api/studies
check "...and keeps one study of four runs" \
  test "$(json 'b.studies.map(s => s.name + ":" + s.runs + ":" + s.source).join(" ")')" = "friction-2x2:4:imported"
req GET /api/studies/friction-2x2
check "...with its four runs' values still" test "$(json 'b.run_parameters.length')" = 4

# A launched study's name is its own: a sweep of that name is refused, nothing imported.
req POST /api/studies -d '{"name": "taken", "base": {"preset": "circular-quick"}, "vary": {"seed": [1]}}'
expect "a launched study 'taken'" 201
echo '{"name": "taken", "base": {"preset": "circular-quick"}, "vary": {"stages.2.target_axial_strain": [0.02]}}' >"$TMP_ROOT/taken.json"
check "a sweep named taken" "$cli" sweep "$TMP_ROOT/taken.json" --out "$TMP_ROOT/taken" --jobs 1
req POST /api/sweeps/import -d "{\"dir\": \"$TMP_ROOT/taken\"}"
expect "...is refused naming dir" 400 'was launched on this server'
req GET /api/studies/taken
check "...and the launched study is as it was: one run, launched" \
  test "$(json 'b.runs + ":" + b.source')" = "1:launched"
req POST /api/studies/taken/cancel

check "server stops cleanly" stop_server
finish
