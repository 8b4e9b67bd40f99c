#!/usr/bin/env python3
"""Every numeric scene key at its extremes: refused naming that key, or run and warned naming
it, or run without a warning because the value is inside the validity envelope.

The keys come from the parser itself (`grainlab scene-keys --json`). Each is set, in a quick
preset that reads it, to 0, -1, 1e-300, 1e300, base x 1e-6 and base x 1e6 (base: the preset's
value, else the key's default, else the exemplar's value). Each case is judged first by
`grainlab check`:
  - exit 2: the error must name the key (the first field of the message);
  - exit 0: the case is run, and must complete; a warning it carries that is not in the
    unchanged preset's run must name the key (a result outside the envelope blamed on
    another field, or unwarned, fails).
Runs are capped so the walk stays cheap: every stage's max_time is cut to 3,000 timesteps
(the timestep `grainlab check` reports), so each run is at most a few thousand steps per stage
of a 250-particle specimen. A run's measured checks see only those steps.

usage: validity_key_walk_test.py GRAINLAB [--keys SUBSTRING] [--keys-from GRAINLAB]
"""
import json
import os
import re
import subprocess
import sys
import tempfile

GRAINLAB = sys.argv[1]
ONLY = sys.argv[sys.argv.index("--keys") + 1] if "--keys" in sys.argv else None
# The catalogue's grainlab, if not GRAINLAB (to walk a build that has no scene-keys command).
KEYS_FROM = sys.argv[sys.argv.index("--keys-from") + 1] if "--keys-from" in sys.argv else GRAINLAB
CAP_STEPS = 3000

# The quick preset that reads a stage key of each stage type (demo-pile for free stages).
STAGE_BASE = {"compaction": "circular-quick", "isotropic": "circular-quick", "biaxial": "circular-quick",
              "rotation": "rotation-circular-quick", "cyclic": "cyclic-circular-quick",
              "simple_shear": "simple-shear-circular-quick", "free": "demo-pile"}


def generalise(path):
    return re.sub(r"\[[0-9]+\]", "[]", path)


def preset(name):
    return json.loads(subprocess.check_output([GRAINLAB, "preset", name]))


def base_scene(key, stage_type):
    """The scene to walk `key` in (for a stage key, of that stage type), and the concrete path
    of the key in it."""
    path = key["path"]
    if path.startswith("stages[]."):
        scene = preset(STAGE_BASE[stage_type])
        index = next(k for k, s in enumerate(scene["stages"]) if s.get("type", "free") == stage_type)
        return scene, path.replace("stages[]", f"stages[{index}]")
    if path.startswith("particles[].members[]"):
        # The pile with its first disc made a clump of two overlapping discs of its radius.
        scene = preset("demo-pile")
        first = scene["particles"][0]
        r = first.pop("radius")
        first["shape"] = "clump"
        first["members"] = [{"position": [-0.8 * r, 0], "radius": r}, {"position": [0.8 * r, 0], "radius": r}]
        return scene, path.replace("[]", "[0]")
    if path.startswith("particles[]") or path.startswith("walls[]"):
        return preset("demo-pile"), path.replace("[]", "[0]")
    scene = preset("circular-quick")
    if path.startswith("boundary."):
        scene = preset("periodic-biaxial-circular-quick")
    if path in ("solver.velocity_iterations", "solver.position_iterations"):
        scene["solver"]["engine"] = "box2d"
    if path in ("assembly.aspect_ratio", "assembly.vertices", "assembly.bedding_angle_deg"):
        scene = preset("elongated-bedding-30-quick")
    if path == "assembly.clump_discs":
        scene = preset("clump-bedding-30-quick")
    return scene, path


def slot(scene, path):
    """(holder, key) of a concrete path such as stages[2].strain_rate."""
    parts = path.split(".")
    at = scene
    for part in parts[:-1]:
        m = re.fullmatch(r"(\w+)\[(\d+)\]", part)
        at = at[m.group(1)][int(m.group(2))] if m else at.setdefault(part, {})
    return at, parts[-1]


def get(scene, path):
    """The value at a concrete path, or None; unlike slot, it adds no empty object on the way
    (an empty "start_from" is itself an error)."""
    at = scene
    for part in path.split("."):
        m = re.fullmatch(r"(\w+)\[(\d+)\]", part)
        at = at.get(m.group(1), [])[int(m.group(2))] if m else at.get(part) if isinstance(at, dict) else None
        if at is None:
            return None
    return at


def put(scene, path, value):
    holder, key = slot(scene, path)
    holder[key] = value
    # A rotation stage takes two of its three speed fields: keep the one walked and one other.
    if key in ("rotation_rate_deg_per_s", "total_rotation_deg", "duration") and holder.get("type") == "rotation":
        others = [k for k in ("duration", "total_rotation_deg", "rotation_rate_deg_per_s") if k != key and k in holder]
        for extra in others[1:]:
            del holder[extra]


def check(scene, workdir):
    path = os.path.join(workdir, "scene.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    p = subprocess.run([GRAINLAB, "check", path], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def capped(scene, timestep):
    scene = json.loads(json.dumps(scene))
    for stage in scene.get("stages", []):
        limit = CAP_STEPS * timestep
        stage["max_time"] = min(stage.get("max_time", limit), limit)
        if stage.get("type", "free") == "free":
            stage["duration"] = min(stage["duration"], limit)
    return scene


def run(scene, workdir):
    path = os.path.join(workdir, "run.json")
    out = os.path.join(workdir, "out")
    with open(path, "w") as f:
        json.dump(scene, f)
    p = subprocess.run([GRAINLAB, "run", path, "--out", out], capture_output=True, text=True, timeout=900)
    summary = {}
    if os.path.exists(os.path.join(out, "summary.json")):
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    return p.returncode, summary, p.stderr


def timestep_of(check_stdout):
    m = re.search(r"timestep ([0-9.e+-]+) s", check_stdout)
    return float(m.group(1))


def warning_keys(summary):
    return {(w["quantity"], w["field"]) for w in summary.get("warnings", [])}


def main():
    keys = json.loads(subprocess.check_output([KEYS_FROM, "scene-keys", "--json"]))["keys"]
    numeric = [k for k in keys if k["kind"] in ("number", "integer")]
    if ONLY:
        numeric = [k for k in numeric if ONLY in k["path"]]
    assert len(numeric) >= 40 or ONLY, f"only {len(numeric)} numeric keys in the catalogue"
    failures, outcomes = [], {"refused": 0, "warned": 0, "inside": 0}
    baseline_warnings = {}
    with tempfile.TemporaryDirectory() as tmp:
        walks = [(key, t) for key in numeric for t in (key.get("stage_types") or [None])]
        for key, stage_type in walks:
            scene, path = base_scene(key, stage_type)
            base_name = json.dumps(scene, sort_keys=True)
            base = get(scene, path)
            if not isinstance(base, (int, float)) or isinstance(base, bool):
                default = key.get("default")
                base = default if isinstance(default, (int, float)) and not isinstance(default, bool) else key["example"]
            if not isinstance(base, (int, float)):
                base = 1
            # The unchanged scene's own warnings (capped run): a case is judged on what it adds.
            if base_name not in baseline_warnings:
                code, out, err = check(scene, tmp)
                assert code == 0, f"the base scene of {path} is refused: {err}"
                code, summary, err = run(capped(scene, timestep_of(out)), tmp)
                assert summary.get("status") == "completed", f"the base scene of {path} did not complete: {err}"
                baseline_warnings[base_name] = warning_keys(summary)
            for value in (0, -1, 1e-300, 1e300, base * 1e-6, base * 1e6):
                case = json.loads(json.dumps(scene))
                put(case, path, value)
                label = f"{path} = {value!r}" + (f" ({stage_type})" if stage_type else "")
                code, out, err = check(case, tmp)
                if code == 2:
                    m = re.match(r"error: ([^:]+):", err)
                    named = m.group(1) if m else ""
                    # A clump's discs must overlap: a member shrunk or moved apart breaks a
                    # relation between members, which the error names as the members list.
                    relation = generalise(named) == "particles[].members" and "connected body" in err
                    if generalise(named) != key["path"] and not (relation and key["path"].startswith("particles[].members[].")):
                        failures.append(f"{label}: refused naming {named!r}: {err.strip()[:300]}")
                    else:
                        outcomes["refused"] += 1
                    continue
                if code != 0:
                    failures.append(f"{label}: check exited {code}: {err.strip()[:300]}")
                    continue
                code, summary, err = run(capped(case, timestep_of(out)), tmp)
                if summary.get("status") != "completed":
                    failures.append(f"{label}: passed check but the run {summary.get('status')}: "
                                    f"{summary.get('error', err.strip())[:300]}")
                    continue
                # Measured warnings (with a step) of a capped run describe a specimen cut short
                # (consolidation not finished): they count when they name the key, and are
                # otherwise left to the full runs of the regression cases.
                added = warning_keys(summary) - baseline_warnings[base_name]
                measured = {(w["quantity"], w["field"]) for w in summary.get("warnings", []) if "step" in w}
                named = {q for q, f in added if generalise(f) == key["path"]}
                others = {(q, f) for q, f in added - measured if generalise(f) != key["path"]}
                if others:
                    failures.append(f"{label}: completed with warnings naming other fields: {sorted(others)}")
                elif named:
                    outcomes["warned"] += 1
                else:
                    outcomes["inside"] += 1
    total = sum(outcomes.values()) + len(failures)
    print(f"{len(numeric)} numeric keys, {len(walks)} key and stage type pairs, {total} cases: {outcomes['refused']} refused naming the key, "
          f"{outcomes['warned']} completed with a warning naming it, {outcomes['inside']} completed inside "
          f"the envelope, {len(failures)} failed")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
