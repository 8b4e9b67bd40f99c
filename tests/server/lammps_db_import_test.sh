#!/usr/bin/env bash
# `grainlab import lammps ... --db`: a LAMMPS run kept in the server's database as a run like any
# other (origin "lammps"): its series is the import's series.csv byte for byte, its stress the
# closed form of the dumps' one contact, its replay frames the dumps' discs and force chain; a
# refused import leaves neither a run nor a folder. Small dumps written here: no LAMMPS needed.
source "$(dirname "$0")/lib.sh"
cli=$GRAINLAB_CLI
d=$TMP_ROOT/dumps
mkdir -p "$d"

# Two discs of radius 0.55 one unit apart along x in a 10 x 10 cell, pushed apart by a normal
# force F (on atom 1: -F x): sigma11 = F * 1 / 100, everything else zero.
atoms() {  # atoms STEP
  printf 'ITEM: TIMESTEP\n%s\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n-0.5 0.5\n' "$1"
  printf 'ITEM: ATOMS id type x y vx vy omegaz radius\n1 1 1 1 0 0 0 0.55\n2 1 2 1 0 0 0 0.55\n'
}
entries() {  # entries STEP F
  printf 'ITEM: TIMESTEP\n%s\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n-0.5 0.5\n' "$1"
  printf 'ITEM: ENTRIES c_ends[1] c_ends[2] c_pairs[1] c_pairs[2] c_pairs[3] c_pairs[4] c_pairs[5]\n1 2 1 -%s 0 0 0\n' "$2"
}
{ atoms 0; atoms 100; atoms 200; } > "$d/particles.dump"
{ entries 0 3; entries 100 4; entries 200 5; } > "$d/contacts.dump"
{ entries 0 3; entries 100 4; entries 300 5; } > "$d/mismatched.dump"

db=$TMP_ROOT/runs.db
out=$("$cli" import lammps "$d/particles.dump" "$d/contacts.dump" --timestep 1e-6 --frames-every 2 \
        --out "$TMP_ROOT/imported" --db "$db" --name "lammps/two-discs" 2>&1)
check "grainlab import lammps --db stores the run" grep -q 'stored as run 1 in .* (origin lammps)' <<<"$out"
check "...and writes the folder as without --db" test -f "$TMP_ROOT/imported/series.csv"

# Refused imports: no clock for the rows, frames of different timesteps. Nothing is left.
"$cli" import lammps "$d/particles.dump" "$d/contacts.dump" --out "$TMP_ROOT/no-clock" --db "$db" 2>"$TMP_ROOT/err"
check "an import without a timestep is refused with status 2" test $? -eq 2
check "...saying what to give" grep -q -- '--db needs the run.s timestep: give --timestep' "$TMP_ROOT/err"
check "...leaving no folder" test ! -e "$TMP_ROOT/no-clock"
"$cli" import lammps "$d/particles.dump" "$d/mismatched.dump" --timestep 1e-6 --out "$TMP_ROOT/bad" --db "$db" \
  2>"$TMP_ROOT/err"
check "frames of different timesteps are refused with status 2" test $? -eq 2
check "...naming the file and line" grep -q 'dump:[0-9]*:' "$TMP_ROOT/err"
check "...leaving no folder" test ! -e "$TMP_ROOT/bad"
"$cli" import lammps "$d/particles.dump" "$d/contacts.dump" --out "$TMP_ROOT/named" --name x 2>"$TMP_ROOT/err"
check "--name without --db is refused with status 2" test $? -eq 2

start_server "$TMP_ROOT/server.log" "$db"
req GET /api/runs
check "the database holds the one import, not the refused ones" test "$(json b.runs.length)" -eq 1
req GET /api/runs/1
expect "the imported run is completed" 200 '"status":"completed"'
check "...its origin is lammps" test "$(json b.origin)" = lammps
check "...named as asked, with its 2 particles and LAMMPS's last step" \
  test "$(json '[b.name, b.particles, b.steps].join()')" = "lammps/two-discs,2,200"
check "...with the shearing-like stage the charts read against strain" \
  test "$(json 'b.scene.stages[0].type')" = lammps_deformation
req GET "/api/runs/1/series?format=csv"
check "its series is the import's series.csv byte for byte" cmp <(printf '%s' "$BODY") "$TMP_ROOT/imported/series.csv"
req GET /api/runs/1/series
check "sigma11 = F * 1 m / 100 m^2 at each frame (F = 3, 4, 5 N/m), to rounding" \
  test "$(json 'b.rows.map((r, k) => Math.abs(r[b.columns.indexOf("sigma11")] / ((3 + k) / 100) - 1) < 1e-14).join()')" \
       = "true,true,true"
req GET /api/runs/1/histograms
check "a histogram per frame for the rose diagrams" test "$(json b.histograms.length)" -eq 3
req GET /api/runs/1/shapes
check "the shapes are the two discs" test "$(json 'b.shapes.map(s => s.disc).join()')" = "0.55,0.55"
req GET /api/runs/1/frames
check "replay frames every 2nd frame and the last: steps 0 and 200" \
  test "$(json 'b.frames.map(f => f.step).join()')" = "0,200"
curl -s --max-time 30 -o "$TMP_ROOT/last.frame" "$(BASE)/api/runs/1/frames?index=1"
# Frame layout (docs/stream-protocol.md): header 40 bytes (particles at 24, chains at 28), then
# x y angle meanForce per particle, then i j fn per chain.
frame=$(node -e "const b = require('fs').readFileSync('$TMP_ROOT/last.frame');
  console.log([b.readUInt32LE(24), b.readUInt32LE(28), b.readFloatLE(40), b.readFloatLE(56),
               b.readUInt32LE(72), b.readUInt32LE(76), b.readFloatLE(80)].join())")
check "the last frame: 2 discs at x = 1 and 2, one chain 0-1 carrying 5 N/m" test "$frame" = "2,1,1,2,0,1,5"
stop_server
finish
