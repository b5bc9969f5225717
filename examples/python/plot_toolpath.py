#!/usr/bin/env python3
"""Plots a program's tool path with matplotlib: rapids dashed, feed moves solid, coloured by
feed, arcs drawn as arcs, moves across the plane (drilling) as dots (docs/embedding.md,
"Python").

    python3 examples/python/plot_toolpath.py examples/macro-basics/bolt-circle.nc --out path.png
    python3 examples/python/plot_toolpath.py part.nc --setup fanuc-0i-mf --set DPI=1 --plane XZ

Without --out it opens a window (MPLBACKEND=Agg and --out for a file only).
"""
import argparse

import matplotlib.pyplot as plt
import numpy as np

import ncvm

AXES = {"XY": (0, 1), "XZ": (0, 2), "YZ": (1, 2)}


def arc_points(move, a, b, steps=24):
    """Points along an arc move in the plane of axes a, b (the centre is move["center"])."""
    cx, cy = move["center"][a], move["center"][b]
    sx, sy = move["start"][a] - cx, move["start"][b] - cy
    ex, ey = move["end"][a] - cx, move["end"][b] - cy
    t0, t1 = np.arctan2(sy, sx), np.arctan2(ey, ex)
    ccw = move["kind"] == "ccw"
    if ccw and t1 <= t0:
        t1 += 2 * np.pi
    if not ccw and t1 >= t0:
        t1 -= 2 * np.pi
    t = np.linspace(t0, t1, steps)
    r = np.hypot(sx, sy)
    return cx + r * np.cos(t), cy + r * np.sin(t)


def plot(result, plane="XY", ax=None):
    a, b = AXES[plane]
    ax = ax or plt.gca()
    moves = result.moves
    feeds = moves["feed"][moves["kind"] != "rapid"]
    norm = plt.Normalize(feeds.min() if len(feeds) else 0, feeds.max() if len(feeds) else 1)
    for m in moves:
        if m["kind"] == "rapid":
            ax.plot([m["start"][a], m["end"][a]], [m["start"][b], m["end"][b]], "--",
                    color="0.6", linewidth=0.8)
            continue
        in_plane = {"XY": 17, "XZ": 18, "YZ": 19}[plane] == m["plane"]
        if m["kind"] in ("cw", "ccw") and in_plane:
            xs, ys = arc_points(m, a, b)
        else:
            xs, ys = [m["start"][a], m["end"][a]], [m["start"][b], m["end"][b]]
        colour = plt.cm.viridis(norm(m["feed"]))
        if np.hypot(xs[-1] - xs[0], ys[-1] - ys[0]) < 1e-9 and len(xs) == 2:
            ax.plot(xs[:1], ys[:1], "o", color=colour, markersize=5)  # across the plane: a hole
        else:
            ax.plot(xs, ys, color=colour, linewidth=1.5)
    ax.set_aspect("equal")
    ax.set_xlabel(plane[0])
    ax.set_ylabel(plane[1])
    title = f"{len(moves)} moves, ended {result.end}"
    if result.alarm:
        title += f": {result.alarm.code} at line {result.alarm.line}"
    ax.set_title(title)
    plt.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="viridis"), ax=ax, label="feed")
    return ax


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("program")
    p.add_argument("--setup", action="append", help="setup file or preset name (repeatable)")
    p.add_argument("--set", action="append", dest="sets", help="KEY=VALUE (repeatable)")
    p.add_argument("--plane", choices=AXES, default="XY")
    p.add_argument("--out", help="write the picture here (PNG, SVG, PDF) instead of a window")
    args = p.parse_args()
    result = ncvm.run(args.program, setup=args.setup, sets=args.sets)
    plt.figure(figsize=(8, 6))
    plot(result, args.plane)
    if args.out:
        plt.savefig(args.out, dpi=120)
    else:
        plt.show()


if __name__ == "__main__":
    main()
