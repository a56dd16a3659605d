#!/usr/bin/env python3
"""Log-log plot of render and build time against sphere count, from the CSV
that `bench_scaling --csv FILE` writes, as an SVG.

Needs only python3 (standard library); no plotting package.

    scripts/plot_scaling.py scaling.csv docs/images/scaling.svg
"""
import csv
import math
import sys

WIDTH, HEIGHT = 720, 460
LEFT, RIGHT, TOP, BOTTOM = 70, 190, 40, 50

# (CSV column, legend, colour, dashed)
SERIES = [
    ("float_ms", "ours, float", "#1f77b4", False),
    ("double_ms", "ours, double", "#9467bd", False),
    ("brute_ms", "brute force, float", "#7f7f7f", False),
    ("embree_ms", "Embree 3, float", "#d62728", False),
    ("build_ms", "ours: build", "#1f77b4", True),
    ("embree_build_high_ms", "Embree: build (high)", "#d62728", True),
]


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def points(rows, column):
    """(N, ms) pairs that were measured (-1 means not run; 0 cannot be drawn)."""
    out = []
    for r in rows:
        if column in r and float(r[column]) > 0:
            out.append((float(r["n"]), float(r[column])))
    return out


def decades(values):
    return math.floor(math.log10(min(values))), math.ceil(math.log10(max(values)))


def main(csv_path, svg_path):
    rows = read(csv_path)
    drawn = [(s, points(rows, s[0])) for s in SERIES]
    drawn = [(s, p) for s, p in drawn if p]
    xs = [x for _, p in drawn for x, _ in p]
    ys = [y for _, p in drawn for _, y in p]
    x0, x1 = decades(xs)
    y0, y1 = decades(ys)
    plot_w, plot_h = WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM

    def px(x):
        return LEFT + (math.log10(x) - x0) / (x1 - x0) * plot_w

    def py(y):
        return TOP + (y1 - math.log10(y)) / (y1 - y0) * plot_h

    svg = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" '
        f'font-family="sans-serif" font-size="12">',
        f'<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>',
        f'<text x="{LEFT}" y="22" font-size="14">bench_scaling: render (solid) and build '
        "(dashed) time against spheres in the field</text>",
    ]
    for d in range(x0, x1 + 1):
        x = px(10**d)
        svg.append(f'<line x1="{x:.1f}" y1="{TOP}" x2="{x:.1f}" y2="{TOP + plot_h}" stroke="#ddd"/>')
        svg.append(f'<text x="{x:.1f}" y="{TOP + plot_h + 18}" text-anchor="middle">10^{d}</text>')
    for d in range(y0, y1 + 1):
        y = py(10**d)
        label = f"{10**d:g} ms" if d < 3 else f"{10**(d - 3):g} s"
        svg.append(f'<line x1="{LEFT}" y1="{y:.1f}" x2="{LEFT + plot_w}" y2="{y:.1f}" stroke="#ddd"/>')
        svg.append(f'<text x="{LEFT - 6}" y="{y + 4:.1f}" text-anchor="end">{label}</text>')
    svg.append(f'<rect x="{LEFT}" y="{TOP}" width="{plot_w}" height="{plot_h}" fill="none" stroke="#444"/>')
    svg.append(f'<text x="{LEFT + plot_w / 2}" y="{HEIGHT - 10}" text-anchor="middle">spheres N</text>')
    for i, ((_, legend, colour, dashed), pts) in enumerate(drawn):
        dash = ' stroke-dasharray="6,4"' if dashed else ""
        path = " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in pts)
        svg.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"{dash}/>')
        for x, y in pts:
            svg.append(f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{colour}"/>')
        ly = TOP + 10 + 20 * i
        lx = LEFT + plot_w + 12
        svg.append(f'<line x1="{lx}" y1="{ly}" x2="{lx + 24}" y2="{ly}" stroke="{colour}" stroke-width="2"{dash}/>')
        svg.append(f'<text x="{lx + 30}" y="{ly + 4}">{legend}</text>')
    svg.append("</svg>")
    with open(svg_path, "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
