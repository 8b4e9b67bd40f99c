#!/usr/bin/env bash
# grainlab export lammps refuses what LAMMPS cannot do faithfully: exit 2, one line naming what
# is not exported, and nothing written. Argument: grainlab.
set -euo pipefail
grainlab=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

refused() {  # WHAT_THE_MESSAGE_NAMES ARGS...
  local names=$1 out=$work/out-$RANDOM code=0
  shift
  "$grainlab" export lammps "$@" --out "$out" > /dev/null 2> "$work/err" || code=$?
  if [[ $code == 2 && $(wc -l < "$work/err") == 1 ]] && grep -q "not exported: .*$names" "$work/err" && [[ ! -e $out ]]; then
    echo "ok   - refused ($names): $(cat "$work/err")"
  else
    echo "FAIL - expected a one-line refusal naming '$names', exit 2, nothing written; got exit $code: $(cat "$work/err")"
    failures=$((failures + 1))
  fi
}

python3 "$here/packing.py" 4 4 > "$work/packing.json"
edit() {  # PYTHON_STATEMENT_ON_s > FILE
  python3 -c "import json, sys; s = json.load(open('$work/packing.json')); $1; json.dump(s, sys.stdout)"
}
refused "membrane ring" --preset circular-quick
# A scene's own cell is exported with its strain-controlled stages; what a servo holds is not.
refused 'stages\[0\] ("compaction").friction' --preset periodic-biaxial-circular-quick --without-local-damping
python3 -c "
import json
s = json.load(open('$work/packing.json'))
del s['walls']
s['boundary'] = {'type': 'periodic', 'size': [0.008, 0.006928]}
json.dump(s, open('$work/cell.json', 'w'))
for name, stage in [('isotropic', {'type': 'isotropic', 'pressure': 1e5, 'strain_rate': 1}),
                    ('constant-stress', {'type': 'biaxial', 'pressure': 1e5, 'strain_rate': 1})]:
    s['stages'] = [stage]
    json.dump(s, open(f'$work/cell-{name}.json', 'w'))"
refused 'stages\[0\] ("isotropic").type "isotropic": held by a stress servo' "$work/cell-isotropic.json"
refused 'lateral "constant_stress": held by a stress servo' "$work/cell-constant-stress.json"
refused '--periodic with a periodic cell' "$work/cell.json" --periodic
refused '--deform with a periodic cell' "$work/cell.json" --deform 0,-1
refused "polygon particles" <(edit 's["particles"][0] = {"shape": "polygon", "vertices": [[-1e-3, -1e-3], [1e-3, -1e-3], [0, 1e-3]], "position": s["particles"][0]["position"]}')
refused "local_damping" --preset demo-pile
refused "rolling_friction" <(edit 's["material"]["rolling_friction"] = 0.1')
refused "not axis-aligned" <(edit 's["walls"][0]["normal"] = [0.6, 0.8]')
refused "fixed or kinematic" <(edit 's["particles"][0]["motion"] = "fixed"')
refused "needs a periodic cell" "$work/packing.json" --deform 0,-1
refused "four walls" <(edit 's["walls"].pop()') --periodic

# And what is exportable is exported.
if "$grainlab" export lammps "$work/packing.json" --out "$work/ok" > /dev/null && [[ -s $work/ok/in.grainlab ]]; then
  echo "ok   - the packing itself is exported"
else
  echo "FAIL - the packing itself was not exported"
  failures=$((failures + 1))
fi
((failures == 0))
