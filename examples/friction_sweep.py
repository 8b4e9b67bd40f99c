#!/usr/bin/env python3
"""A friction sweep from Python: the same biaxial test at several interparticle friction
coefficients, the stress ratio and the non-coaxiality plotted against axial strain.

    PYTHONPATH=build/python python3 examples/friction_sweep.py [--preset circular-quick]
        [--frictions 0.1 0.3 0.5 0.7] [--out friction_sweep.png] [--quick]

--quick runs two frictions only, 0 and 0.5 (the test suite runs it so). The script checks
what the physics says must hold: friction between the particles raises the peak mobilised
friction angle of the assembly above that of frictionless particles. For discs it saturates
beyond μ ≈ 0.3 (they roll instead of sliding), so only the ends of the sweep are compared,
and by more than 2°: twice the scatter of the peak between runs of a few hundred discs
(about 1°). It exits non-zero if that does not hold."""
import argparse
import sys

import grainlab


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--preset", default="circular-quick")
    parser.add_argument("--frictions", type=float, nargs="+", default=[0.0, 0.1, 0.3, 0.5, 0.7])
    parser.add_argument("--out", default="friction_sweep.png", help="the figure (needs matplotlib)")
    parser.add_argument("--quick", action="store_true", help="two frictions only, 0 and 0.5")
    args = parser.parse_args()
    frictions = [0.0, 0.5] if args.quick else sorted(args.frictions)

    runs = {}
    # The series labels rows with the stage's name; the shearing stage is the biaxial one.
    shearing = next(st.get("name", "biaxial") for st in grainlab.preset(args.preset)["stages"]
                    if st["type"] == "biaxial")
    for mu in frictions:
        scene = grainlab.preset(args.preset)
        scene["name"] = f"{args.preset}-mu{mu}"
        scene["material"]["friction"] = mu  # the compaction stage keeps its own friction (0)
        run = grainlab.run(scene, progress=False)
        if run.status != "completed":
            sys.exit(f"mu = {mu}: run {run.status}: {run.summary.get('error')}")
        runs[mu] = run
        print(f"mu = {mu:4.2f}: peak phi_mob = {run.summary['peak_phi_mob_deg']:5.2f} deg, "
              f"{run.summary['steps']} steps in {run.summary['wall_seconds']:.1f} s")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed: no figure")
    else:
        fig, (top, bottom) = plt.subplots(2, 1, figsize=(6, 6.5), sharex=True)
        for mu, run in runs.items():
            s = run.series[run.series["stage"] == shearing]
            top.plot(100 * s["axial_strain"], s["q"] / s["p"], label=f"μ = {mu}")
            bottom.plot(100 * s["axial_strain"], s["omega_macro_deg"], label=f"μ = {mu}")
        top.set_ylabel("q / p")
        top.legend()
        bottom.set_ylabel("ω (macro), degrees")
        bottom.set_xlabel("axial strain ε₂₂, %")
        fig.suptitle(f"{args.preset}: biaxial test at constant lateral stress")
        fig.tight_layout()
        fig.savefig(args.out, dpi=110)
        print(f"figure: {args.out}")

    peaks = {mu: runs[mu].summary["peak_phi_mob_deg"] for mu in frictions}
    low, high = frictions[0], frictions[-1]
    if low <= 0.05 and high >= 0.3 and not peaks[high] - peaks[low] > 2.0:
        sys.exit(f"peak phi_mob at mu = {high} is not above the one at mu = {low} by 2 degrees: {peaks}")


if __name__ == "__main__":
    main()
