"""Fixture: one `grainlab run --preset circular-quick --vtk` shared by the tests that compare
the module, the analysis and the VTK frames against the CLI's own files."""
import os
import shutil
import sys

from support import CLI_RUN, PRESET, run_cli

shutil.rmtree(CLI_RUN, ignore_errors=True)
os.makedirs(os.path.dirname(CLI_RUN), exist_ok=True)
result = run_cli("run", "--preset", PRESET, "--vtk", "--out", CLI_RUN)
if result.returncode != 0:
    sys.exit(f"grainlab run failed ({result.returncode}):\n{result.stderr}")
print(f"{PRESET} written to {CLI_RUN}")
