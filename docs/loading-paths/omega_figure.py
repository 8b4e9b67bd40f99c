"""The figure of docs/loading-paths.md: omega_strain_rate_deg (θσ − θ_strain_rate) against the
rotation of the principal strain-rate axes, from the series.csv of rotation runs.

    python3 docs/loading-paths/omega_figure.py OUT.svg "LABEL=DIR[,DIR...]" ...

Each LABEL is one panel; its DIRs (one per seed) are drawn thin, their mean bold (the mean of
an axial angle is taken on 2ω). The rotation angle is θ_strain_rate unwrapped from the stage's
initial direction (--initial, default 90°). Standard library only.
"""
import argparse
import csv
import math


def wrap90(a):
    return (a + 90.0) % 180.0 - 90.0


def read_run(directory, stage, initial):
    xs, ys = [], []
    previous = initial
    turned = 0.0
    with open(f"{directory}/series.csv") as f:
        for row in csv.DictReader(f):
            if row["stage"] != stage or not row["theta_strain_rate_deg"] or not row["omega_strain_rate_deg"]:
                continue
            theta = float(row["theta_strain_rate_deg"])
            turned += wrap90(theta - previous)  # samples are far closer than 90° apart
            previous = theta
            xs.append(turned)
            ys.append(float(row["omega_strain_rate_deg"]))
    return xs, ys


def axial_mean(values):
    s = sum(math.sin(math.radians(2 * v)) for v in values)
    c = sum(math.cos(math.radians(2 * v)) for v in values)
    return 0.5 * math.degrees(math.atan2(s, c))


def polyline(points, colour, width, opacity):
    # Break the line where ω wraps through ±90° rather than draw a vertical stroke across.
    parts, current = [], []
    for k, p in enumerate(points):
        if current and abs(p[2] - points[k - 1][2]) > 90:
            parts.append(current)
            current = []
        current.append(p)
    parts.append(current)
    out = []
    for part in parts:
        if len(part) < 2:
            continue
        d = " ".join(f"{x:.1f},{y:.1f}" for x, y, _ in part)
        out.append(f'<polyline points="{d}" fill="none" stroke="{colour}" stroke-width="{width}" '
                   f'stroke-opacity="{opacity}"/>')
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("panels", nargs="+", help="LABEL=DIR[,DIR...]")
    ap.add_argument("--stage", default="rotation")
    ap.add_argument("--initial", type=float, default=90.0)
    args = ap.parse_args()

    colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd"]
    width, height = 430, 300
    left, right, top, bottom = 55, 15, 35, 45
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width * len(args.panels)}" height="{height}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="100%" height="100%" fill="white"/>']
    for k, panel in enumerate(args.panels):
        label, dirs = panel.split("=", 1)
        runs = [read_run(d, args.stage, args.initial) for d in dirs.split(",")]
        xmax = max(max(xs) for xs, _ in runs if xs)
        x0 = k * width + left
        pw, ph = width - left - right, height - top - bottom
        sx = lambda x: x0 + pw * x / xmax
        sy = lambda y: top + ph * (90 - y) / 180
        svg.append(f'<text x="{x0 + pw / 2}" y="20" text-anchor="middle" font-weight="bold">{label} '
                   f'({f"{len(runs)} seeds" if len(runs) > 1 else "one packing"})</text>')
        for y in range(-90, 91, 30):
            svg.append(f'<line x1="{x0}" x2="{x0 + pw}" y1="{sy(y)}" y2="{sy(y)}" stroke="#ddd"/>')
            svg.append(f'<text x="{x0 - 6}" y="{sy(y) + 4}" text-anchor="end">{y}</text>')
        step = 90 if xmax > 200 else 30
        for x in range(0, int(xmax) + 1, step):
            svg.append(f'<line x1="{sx(x)}" x2="{sx(x)}" y1="{top}" y2="{top + ph}" stroke="#ddd"/>')
            svg.append(f'<text x="{sx(x)}" y="{top + ph + 16}" text-anchor="middle">{x}</text>')
        svg.append(f'<rect x="{x0}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="#444"/>')
        svg.append(f'<text x="{x0 + pw / 2}" y="{height - 8}" text-anchor="middle">rotation of the strain-rate '
                   f'axes (°)</text>')
        svg.append(f'<text transform="translate({x0 - 40},{top + ph / 2}) rotate(-90)" text-anchor="middle">'
                   f'ω = θσ − θ_ε̇ (°)</text>')
        colour = colours[k % len(colours)]
        single = len(runs) == 1  # one packing: its own line is the result, drawn bold
        for xs, ys in runs:
            svg.append(polyline([(sx(x), sy(y), y) for x, y in zip(xs, ys)], colour, 2.2 if single else 1,
                                1 if single else 0.35))
        n = min(len(xs) for xs, _ in runs)
        if len(runs) > 1 and n > 1:
            mean = [(sx(runs[0][0][i]), sy(axial_mean([ys[i] for _, ys in runs])),
                     axial_mean([ys[i] for _, ys in runs])) for i in range(n)]
            svg.append(polyline(mean, colour, 2.2, 1))
    svg.append("</svg>")
    with open(args.out, "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()
