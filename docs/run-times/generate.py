#!/usr/bin/env python3
"""Measures how long grainlab's presets, the paper study and the trade-off study take, and
writes docs/run-times.md from the measurements.

    python3 docs/run-times/generate.py --grainlab build/grainlab [--presets A,B] [--no-studies]
        [--out docs/run-times.md]

Each preset runs once with `grainlab run`, one run at a time, so that a run's CPU time is that
of one core. The CPU time is the child process's own (user + system, from the kernel): on a
machine shared with other work it moves far less than the wall time, which is given beside it.
`--check` runs a small subset into a temporary directory and checks the table against each
run's summary.json, and that the published page has a row for every preset, instead of
writing the page (the test suite runs it).
"""
import argparse
import json
import math
import os
import platform
import re
import resource
import subprocess
import sys
import tempfile
import time
from datetime import datetime, timezone


def run_measured(cmd, cwd=None):
    """Runs cmd; returns (wall seconds, CPU seconds of the child, completed process)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    done = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if done.returncode != 0:
        sys.exit(f"run-times: {' '.join(cmd)} failed ({done.returncode}): {done.stderr.strip()[-400:]}")
    return wall, cpu, done


def check_bounds(grainlab, preset):
    """The bounds `grainlab check` gives before the run: the least steps and, at the fastest
    rate it assumes, the least CPU seconds; and, where stages end on a criterion, the most
    steps and, at the slowest rate, the most seconds. Computed from the numbers it prints, not
    from its rounded durations."""
    out = subprocess.run([grainlab, "check", "--preset", preset], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True).stdout
    particles = re.search(r"s, (\d+) particles", out)
    least = re.search(r"lower bound ([0-9.e+-]+) steps.*?at up to ([0-9.e+-]+) M particle-steps/s", out)
    most = re.search(r"at most ([0-9.e+-]+) steps \(at most .*? at ([0-9.e+-]+) M particle-steps/s", out)
    if not particles or not least:
        sys.exit(f"run-times: cannot read the bounds of grainlab check --preset {preset}: {out.strip()}")
    n = int(particles.group(1))
    bounds = {"bound_steps": float(least.group(1)), "bound_s": float(least.group(1)) * n / (float(least.group(2)) * 1e6),
              "most_steps": float("nan"), "most_s": float("nan")}
    if most:
        bounds["most_steps"] = float(most.group(1))
        bounds["most_s"] = float(most.group(1)) * n / (float(most.group(2)) * 1e6)
    return bounds


def measure_preset(grainlab, preset, work):
    scene = os.path.join(work, f"{preset}.json")
    with open(scene, "w") as f:
        f.write(subprocess.run([grainlab, "preset", preset], stdout=subprocess.PIPE, text=True, check=True).stdout)
    out = os.path.join(work, preset)
    wall, cpu, _ = run_measured([grainlab, "run", scene, "--out", out])
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    steps, particles = int(summary["steps"]), int(summary["particles"])
    return {
        "name": preset,
        "particles": particles,
        "steps": steps,
        "cpu_s": cpu,
        "wall_s": wall,
        "rate": particles * steps / cpu if cpu > 0 else float("nan"),
        **check_bounds(grainlab, preset),
        "summary": summary,
    }


def measure_study(grainlab, name, args, work):
    wall, cpu, _ = run_measured([grainlab] + args + ["--out", os.path.join(work, name.split()[1])])
    return {"name": name, "cpu_s": cpu, "wall_s": wall, "command": "grainlab " + " ".join(args) + " --out DIR"}


def fmt(seconds):
    return f"{seconds:.1f}" if seconds < 100 else f"{seconds:.0f}"


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} hardware threads, {platform.system()} {platform.release()}"


def commit():
    here = os.path.dirname(os.path.abspath(__file__))
    done = subprocess.run(["git", "-C", here, "rev-parse", "--short", "HEAD"], stdout=subprocess.PIPE,
                          stderr=subprocess.DEVNULL, text=True)
    return done.stdout.strip() or "unknown"


def render(rows, studies, context):
    lines = [
        "# Run times",
        "",
        "How long each preset and study takes, measured, on one stated machine. This page is",
        "written by `python3 docs/run-times/generate.py --grainlab build/grainlab` (it runs every",
        "preset once, one at a time); rerun it to measure your own machine.",
        "",
        f"- **Machine**: {context['machine']}; load average {context['load_before']} before and "
        f"{context['load_after']} after (1-minute).",
        f"- **Build**: commit {context['commit']}, Release (`./scripts/build`); measured "
        f"{context['date']}.",
        "- **CPU s** is the run's own processor time, the time it would take on one idle core;",
        "  **wall s** what it took here, with whatever else the machine was doing. Particle-steps/s",
        "  is particles × steps / CPU s (the ring's particles included; compare `grainlab bench`,",
        "  docs/benchmarks.md, for the step alone).",
        "- **check's bounds** are what `grainlab check --preset NAME` says before the run: the",
        "  least steps (those of the stages whose length is known) and the least CPU time (those",
        "  steps at the fastest rate a run of that kind steps at); and, where stages end on a",
        "  criterion (compaction to a void ratio, consolidation to equilibrium), the most steps and",
        "  CPU time if every stage ran to its time limit at the slowest rate. Every run lies",
        "  between them; the generator checks it.",
        "",
        "| preset | particles | steps | check's least steps | CPU s | wall s | particle-steps/s | check's least CPU s | check's most CPU s |",
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for r in rows:
        most = fmt(r["most_s"]) if math.isfinite(r["most_s"]) else "—"
        lines.append(f"| {r['name']} | {r['particles']:,} | {r['steps']:,} | {r['bound_steps']:,.0f} | {fmt(r['cpu_s'])} | "
                     f"{fmt(r['wall_s'])} | {r['rate'] / 1e6:.2f} M | {r['bound_s']:.2g} | {most} |")
    if studies:
        lines += ["", "| study | command | CPU s | wall s |", "| --- | --- | ---: | ---: |"]
        for s in studies:
            lines.append(f"| {s['name']} | `{s['command']}` | {fmt(s['cpu_s'])} | {fmt(s['wall_s'])} |")
        lines += ["", "The studies run their runs on as many threads as the machine has (`--jobs`), so their CPU time",
                  "can exceed their wall time. The full paper study (six 160 mm assemblies) and the full",
                  "trade-off are in docs/paper-reproduction.md and docs/speed-accuracy.md, each with its own",
                  "measured time."]
    return "\n".join(lines) + "\n"


def check_rows(rows):
    """The table must say what the runs' own summaries say."""
    for r in rows:
        s = r["summary"]
        assert s["status"] == "completed", f"{r['name']}: status {s['status']}"
        assert r["steps"] > 0 and r["particles"] > 0, r["name"]
        assert 0 < r["cpu_s"], f"{r['name']}: no CPU time measured"
        # The run's own wall clock (summary.json) cannot exceed the process's.
        assert float(s["wall_seconds"]) <= r["wall_s"] + 0.05, f"{r['name']}: summary wall {s['wall_seconds']} > {r['wall_s']}"
        assert abs(r["rate"] - r["particles"] * r["steps"] / r["cpu_s"]) < 1e-6 * r["rate"]
        assert r["bound_s"] > 0, f"{r['name']}: no lower bound read from grainlab check"
        # Bounds the run beats are no bounds (the steps are printed to 3 significant digits).
        assert r["bound_steps"] <= r["steps"] * 1.005, f"{r['name']}: {r['steps']} steps < least {r['bound_steps']}"
        assert r["bound_s"] <= r["cpu_s"], f"{r['name']}: check's least {r['bound_s']:.3g} s > CPU {r['cpu_s']:.3g} s"
        if math.isfinite(r["most_s"]):
            assert r["steps"] <= r["most_steps"] * 1.005, f"{r['name']}: {r['steps']} steps > most {r['most_steps']}"
            assert r["cpu_s"] <= r["most_s"], f"{r['name']}: CPU {r['cpu_s']:.3g} s > check's most {r['most_s']:.3g} s"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--grainlab", required=True)
    parser.add_argument("--presets", help="comma-separated (default: every preset)")
    parser.add_argument("--no-studies", action="store_true")
    parser.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "run-times.md"))
    parser.add_argument("--check", action="store_true", help="measure circular-quick and demo-pile and check them")
    parser.add_argument("--commit", help="the commit the binary was built from (default: this checkout's HEAD)")
    args = parser.parse_args()
    grainlab = os.path.abspath(args.grainlab)
    if args.check:
        presets = ["demo-pile", "circular-quick"]
    elif args.presets:
        presets = args.presets.split(",")
    else:
        presets = subprocess.run([grainlab, "presets"], stdout=subprocess.PIPE, text=True, check=True).stdout.split()
    load_before = f"{os.getloadavg()[0]:.2f}"
    with tempfile.TemporaryDirectory(prefix="grainlab-run-times-") as work:
        rows = []
        for k, p in enumerate(presets):
            print(f"run-times: [{k + 1}/{len(presets)}] {p}", file=sys.stderr, flush=True)
            rows.append(measure_preset(grainlab, p, work))
        studies = []
        if not args.no_studies and not args.check:
            print("run-times: paper --quick --seeds 1, tradeoff --quick", file=sys.stderr, flush=True)
            studies.append(measure_study(grainlab, "paper quick", ["paper", "--quick", "--seeds", "1"], work))
            studies.append(measure_study(grainlab, "tradeoff quick", ["tradeoff", "--quick"], work))
    context = {"machine": machine(), "load_before": load_before, "load_after": f"{os.getloadavg()[0]:.2f}",
               "commit": args.commit or commit(), "date": datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC")}
    if args.check:
        check_rows(rows)
        page = render(rows, studies, context)
        assert all(f"| {p} |" in page for p in presets)
        # The page in the repository must cover every preset the binary offers.
        every = subprocess.run([grainlab, "presets"], stdout=subprocess.PIPE, text=True, check=True).stdout.split()
        try:
            with open(args.out) as f:
                published = f.read()
        except OSError as e:
            sys.exit(f"run-times: cannot read {args.out} ({e.strerror}): generate it "
                     "(python3 docs/run-times/generate.py --grainlab build/grainlab)")
        missing = [p for p in every if f"| {p} |" not in published]
        if missing:
            sys.exit(f"run-times: {args.out} has no row for {', '.join(missing)}: regenerate it "
                     "(python3 docs/run-times/generate.py --grainlab build/grainlab)")
        print(f"run-times: checked {len(rows)} runs, and {len(every)} presets in {os.path.normpath(args.out)}")
        return
    check_rows(rows)  # a page whose runs beat their bounds is not written
    with open(args.out, "w") as f:
        f.write(render(rows, studies, context))
    print(f"run-times: wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
