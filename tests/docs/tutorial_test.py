#!/usr/bin/env python3
"""Runs docs/tutorial.md: every fenced block whose info string is `sh tutorial` or
`python tutorial`, in order, in a fresh folder where `build` points at the build tree (the
tutorial's commands use build/grainlab and build/python, as from the repository's top).
Fails if any block fails, or if a figure or file the tutorial names (`tutorial/...`) is
missing afterwards. The tutorial keeps its runs small (quick presets, short strains), so it
runs in well under a minute on two free cores."""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

source, build = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
doc = (source / "docs" / "tutorial.md").read_text(encoding="utf-8")
blocks = re.findall(r"^```(sh|python) tutorial\n(.*?)^```", doc, re.M | re.S)
if not blocks:
    sys.exit("docs/tutorial.md has no `sh tutorial` or `python tutorial` blocks")

with tempfile.TemporaryDirectory(prefix="grainlab-tutorial-") as work:
    work = pathlib.Path(work)
    (work / "build").symlink_to(build)
    env = dict(os.environ, MPLBACKEND="Agg")
    for k, (language, code) in enumerate(blocks, 1):
        print(f"--- block {k} ({language}) ---\n{code}", flush=True)
        if language == "sh":
            command = ["bash", "-euo", "pipefail", "-c", code]
        else:
            script = work / f"block{k}.py"
            script.write_text(code, encoding="utf-8")
            command = ["/usr/bin/python3", str(script)]
            env["PYTHONPATH"] = str(build / "python")
        result = subprocess.run(command, cwd=work, env=env, text=True, capture_output=True)
        print(result.stdout[-3000:], result.stderr[-3000:], sep="\n", flush=True)
        if result.returncode != 0:
            sys.exit(f"block {k} failed with status {result.returncode}")
    named = set(re.findall(r"`(tutorial/[\w./-]+\.(?:png|csv|json|pvd))`", doc))
    missing = sorted(p for p in named if not (work / p).exists())
    if missing:
        sys.exit(f"the tutorial names files its commands did not make: {missing}")
    print(f"ok: {len(blocks)} blocks ran; {len(named)} named files exist")
