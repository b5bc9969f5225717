#!/usr/bin/env python3
"""Writes a 3-axis finishing program for the mill stock benchmark (docs/performance.md):
a Ø6 ball raster in X over z = -3 + 2 sin(x/10) cos(y/15) on a 112 x 112 mm block, in
short G01 segments, and its setup (stock cells 0.05 mm).

    bench/gen_mill_finish.py DIR [--moves 100000]   -> DIR/mill_finish.nc, DIR/mill_finish.toml
"""
import argparse
import math
import os

ap = argparse.ArgumentParser()
ap.add_argument("dir")
ap.add_argument("--moves", type=int, default=100000)
args = ap.parse_args()
os.makedirs(args.dir, exist_ok=True)

side, margin = 112.0, 4.0
segment = 0.28
per_line = int((side - 2 * margin) / segment)
lines = max(1, -(-args.moves // per_line))
step = (side - 2 * margin) / lines


def z(x, y):
    return -3 + 2 * math.sin(x / 10) * math.cos(y / 15)


out = ["%", "O0300 (MILL FINISHING BENCHMARK)", "G90 G17 G21 G40 G49 G80", "T1 M06",
       "G54 G00 X%.3f Y%.3f" % (margin, margin), "G43 H1 Z10.", "S8000 M03", "G01 F3000."]
moves = 0
for k in range(lines):
    y = margin + k * step
    out.append("G01 X%.3f Y%.3f Z%.4f" % (margin, y, z(margin, y)))
    for s in range(1, per_line + 1):
        if moves >= args.moves:
            break
        x = margin + s * segment
        out.append("X%.3f Z%.4f" % (x, z(x, y)))
        moves += 1
out += ["G00 Z10.", "M30", "%"]
with open(os.path.join(args.dir, "mill_finish.nc"), "w") as f:
    f.write("\n".join(out) + "\n")
with open(os.path.join(args.dir, "mill_finish.toml"), "w") as f:
    f.write("""[machine]
kind = "mill"
[axes.Z]
initial = 50.0
[tool_offsets.1]
h_geometry = 0.0
[tools.1]
type = "ball"
diameter = 6.0
[stock]
min = [0.0, 0.0, -10.0]
max = [112.0, 112.0, 0.0]
cell = 0.05
""")
print(os.path.join(args.dir, "mill_finish.nc"))
