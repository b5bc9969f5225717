#!/usr/bin/env python3
"""A CAM-like mill program of about N short G01 moves (default 100,000) and its setup with a
[stock]: a zigzag over a 100 x 100 mm block at Z-1 with a 6 mm end mill, 0.5 mm steps along X,
rows 0.2 mm apart; the stock in 0.1 mm cells (1,100 x 1,100). Writes DIR/big.nc, DIR/big.toml."""
import sys

moves = int(sys.argv[2]) if len(sys.argv) > 2 else 100_000
out = sys.argv[1]
lines = ["O0100 (STOCK SNAPSHOT BENCHMARK)", "G21 G90 G17 G40 G80", "T1 M06", "G00 X0 Y0 Z5.",
         "G01 Z-1. F3000."]
n, row = 0, 0
while n < moves - 6:
    for k in range(200):
        x = (k + 1) * 0.5 if row % 2 == 0 else 100 - (k + 1) * 0.5
        lines.append(f"X{x:.3f}")
        n += 1
    row = (row + 1) % 501
    lines.append(f"Y{row * 0.2:.3f}")
    n += 1
lines += ["G00 Z50.", "M30"]
with open(f"{out}/big.nc", "w") as f:
    f.write("\n".join(lines) + "\n")
with open(f"{out}/big.toml", "w") as f:
    f.write('[machine]\nkind = "mill"\nunits = "mm"\n[tools.1]\ntype = "flat"\ndiameter = 6.0\n'
            '[stock]\nmin = [-5.0, -5.0, -20.0]\nmax = [105.0, 105.0, 0.0]\ncell = 0.1\n')
