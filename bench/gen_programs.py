#!/usr/bin/env python3
"""Generate the benchmark workload programs for ncvm (docs/performance.md).

    bench/gen_programs.py OUTDIR                       # the four default workloads
    bench/gen_programs.py OUTDIR --only linear --lines 10000000

Workloads (file names carry the size: 1000000 -> "1m", 200000 -> "200k"):

  linear_<n>.nc  --lines N       N G01 moves in X Y Z, CAM style (3 decimals, trailing zeros
                                 dropped, decimal point always written), a raster over a
                                 wavy surface; an N number on every 10th line.
  mixed_<n>.nc   --mixed N       N moves mixing G00 / G01 / G02 / G03; arcs use I J from the
                                 start point, the end radius matches the start radius to
                                 0.001 mm (checked here).
  while_<n>.nc   --iterations N  one Fanuc WHILE loop of N iterations computing points of a
                                 rotated ellipse with SIN/COS (ten lines in the body, one of
                                 them a G01 move), ending with M30.
  sub_<n>.nc     --calls N       main program O0001 calling O0100 N times with M98 (one
                                 M98 block per call, a G00 repositioning every 100 calls),
                                 M30; then O0100: a small G91 square pocket step, M99.

--dialect rs274 writes the same workloads for LinuxCNC's rs274 (bench/peers) as .ngc files:
no % or O-number lines (a bare O number is an O-word there), bracketed expressions, the
loop as `o100 while` / `o100 endwhile`, the subprogram as `o100 sub` ... `o100 endsub`
(defined before the main program, as rs274 requires) called by `o100 call`.

The output is deterministic (fixed --seed). Every program keeps within ncvm's default
limits (simulated machine time < 100 h, blocks < 10^8, file < 512 MB) up to 10^7 lines.
"""

from __future__ import annotations

import argparse
import math
import os
import random
import sys

CHUNK = 1 << 16  # lines buffered before a write


def size_tag(n: int) -> str:
    if n >= 1_000_000 and n % 1_000_000 == 0:
        return f"{n // 1_000_000}m"
    if n >= 1_000 and n % 1_000 == 0:
        return f"{n // 1_000}k"
    return str(n)


def num(v: float) -> str:
    """A length the way CAM posts write it: 3 decimals, no trailing zeros, point kept."""
    s = f"{v:.3f}".rstrip("0")
    if s in ("-0.", "-."):
        s = "0."
    return s


class Writer:
    def __init__(self, path: str):
        self.f = open(path, "w", encoding="ascii", newline="\n")
        self.buf: list[str] = []

    def line(self, s: str) -> None:
        self.buf.append(s)
        if len(self.buf) >= CHUNK:
            self.flush()

    def flush(self) -> None:
        if self.buf:
            self.f.write("\n".join(self.buf))
            self.f.write("\n")
            self.buf.clear()

    def close(self) -> None:
        self.flush()
        self.f.close()


# ---------------------------------------------------------------------------------------------
def header(w: Writer, rs274: bool, title: str) -> None:
    """Program start: `%` and an O-number line for Fanuc, a comment for rs274."""
    if rs274:
        w.line(f"({title})")
    else:
        w.line("%")
        w.line(f"O0001 ({title})")


def footer(w: Writer, rs274: bool) -> None:
    w.line("M30")
    if not rs274:
        w.line("%")


def gen_linear(path: str, lines: int, rs274: bool = False) -> None:
    """Raster finishing pass over z = f(x, y): X zigzags across 0..120 mm in 0.25..0.45 mm
    steps, Y steps over 0.5 mm at each end and wanders 0.15 mm along a pass, Z follows the
    surface. Every line moves X, Y and
    Z (a 3-axis finishing toolpath as posted by CAM)."""
    w = Writer(path)
    header(w, rs274, f"LINEAR {lines} MOVES")
    w.line("G90 G21 G17 G40 G49 G80 G54")
    w.line("G00 X0. Y0. Z5.")
    w.line("G01 Z0. F3000.")
    x, y, direction = 0.0, 0.0, 1.0
    xmax = 120.0
    k = 0
    for i in range(1, lines + 1):
        k = (k * 1103515245 + 12345) & 0x7FFFFFFF  # cheap LCG: steps vary like real data
        step = 0.25 + (k % 201) * 0.001
        x += direction * step
        if x > xmax or x < 0.0:
            x = min(max(x, 0.0), xmax)
            direction = -direction
            y += 0.5
            if y > 120.0:
                y = 0.0
        z = -2.0 + 1.5 * math.sin(x * 0.05) * math.cos(y * 0.04) + 0.3 * math.sin(x * 0.31 + y * 0.17)
        yy = y + 0.15 * math.sin(x * 0.7)  # slight wander across the raster line
        body = f"X{num(x)} Y{num(yy)} Z{num(z)}"
        if i % 10 == 0:
            w.line(f"N{i % 100_000_000} {body}")
        else:
            w.line(body)
    w.line("G00 Z5.")
    footer(w, rs274)
    w.close()


# ---------------------------------------------------------------------------------------------
def gen_mixed(path: str, moves: int, seed: int, rs274: bool = False) -> None:
    """About 10% G00, 40% G01, 25% G02, 25% G03 in the box -100..100 mm. Arc ends are
    rounded to 0.001 mm; the generator checks |r_end - r_start| <= 0.001 mm."""
    rng = random.Random(seed)
    w = Writer(path)
    header(w, rs274, f"MIXED {moves} MOVES")
    w.line("G90 G21 G17 G40 G49 G80 G54")
    w.line("G00 X0. Y0. Z2.")
    w.line("G01 Z-1. F5000.")
    ix, iy = 0, 0  # current position in micrometres (exact, as the control sees it)
    lim = 100_000
    worst = 0.0
    mode = None
    i = 0
    while i < moves:
        r = rng.random()
        if r < 0.10:  # rapid anywhere in the box
            ix, iy = rng.randint(-lim, lim), rng.randint(-lim, lim)
            g = "G00"
            words = f"X{num(ix / 1000)} Y{num(iy / 1000)}"
        elif r < 0.50:  # short feed move, pulled back towards the centre near the edge
            ang = rng.uniform(0, 2 * math.pi)
            length = rng.uniform(0.5, 6.0)
            nx = ix + round(length * 1000 * math.cos(ang))
            ny = iy + round(length * 1000 * math.sin(ang))
            if abs(nx) > lim or abs(ny) > lim:
                nx, ny = ix // 2, iy // 2
            ix, iy = nx, ny
            g = "G01"
            words = f"X{num(ix / 1000)} Y{num(iy / 1000)}"
        else:  # arc: centre at I J from the start, end on the same circle
            cw = r < 0.75
            g = "G02" if cw else "G03"
            rad = rng.uniform(1.0, 12.0)
            a0 = rng.uniform(0, 2 * math.pi)  # direction from centre to start
            I = round(-rad * 1000 * math.cos(a0))
            J = round(-rad * 1000 * math.sin(a0))
            cx, cy = ix + I, iy + J
            if abs(cx) > lim - 13_000 or abs(cy) > lim - 13_000:
                I, J = -I, -J  # mirror the centre to the other side, towards the box centre
                cx, cy = ix + I, iy + J
            rs = math.hypot(I, J)
            start = math.atan2(iy - cy, ix - cx)
            sweep = math.radians(rng.uniform(10.0, 300.0)) * (-1 if cw else 1)
            ex = cx + round(rs * math.cos(start + sweep))
            ey = cy + round(rs * math.sin(start + sweep))
            dev = abs(math.hypot(ex - cx, ey - cy) - rs) / 1000.0
            if dev > 0.001:
                raise SystemExit(f"gen_programs: arc radius mismatch {dev} mm")
            worst = max(worst, dev)
            ix, iy = ex, ey
            words = f"X{num(ix / 1000)} Y{num(iy / 1000)} I{num(I / 1000)} J{num(J / 1000)}"
        # Modal G code written only when it changes, as posts do.
        w.line(words if g == mode else f"{g} {words}")
        mode = g
        i += 1
    w.line("G00 Z5.")
    footer(w, rs274)
    w.close()
    print(f"  mixed: worst arc end-radius deviation {worst:.4f} mm", file=sys.stderr)


# ---------------------------------------------------------------------------------------------
def gen_while(path: str, iterations: int, rs274: bool = False) -> None:
    """An ellipse (a = 50, b = 30, rotated 15 degrees) traced in 0.36-degree steps."""
    if rs274:
        gen_while_rs274(path, iterations)
        return
    text = f"""%
O0002 (WHILE LOOP {iterations} ITERATIONS)
G90 G21 G17 G40 G49 G80 G54
G00 X50. Y0. Z2.
G01 Z-1. F3000.
#100={iterations}
#101=50.
#102=30.
#103=15.
#104=0.36
#1=0
WHILE[#1LT#100]DO1
#2=#1*#104
#3=#101*COS[#2]
#4=#102*SIN[#2]
#5=COS[#103]
#6=SIN[#103]
#7=#3*#5-#4*#6
#8=#3*#6+#4*#5
G01 X#7 Y#8
#1=#1+1
END1
G00 Z5.
M30
%
"""
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write(text)


def gen_while_rs274(path: str, iterations: int) -> None:
    """The same loop for rs274: an O-word while, binary operations in brackets."""
    text = f"""(WHILE LOOP {iterations} ITERATIONS)
G90 G21 G17 G40 G49 G80 G54
G00 X50. Y0. Z2.
G01 Z-1. F3000.
#100={iterations}
#101=50.
#102=30.
#103=15.
#104=0.36
#1=0
o100 while [#1 LT #100]
#2=[#1*#104]
#3=[#101*COS[#2]]
#4=[#102*SIN[#2]]
#5=COS[#103]
#6=SIN[#103]
#7=[#3*#5-#4*#6]
#8=[#3*#6+#4*#5]
G01 X#7 Y#8
#1=[#1+1]
o100 endwhile
G00 Z5.
M30
"""
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write(text)


# ---------------------------------------------------------------------------------------------
def gen_sub(path: str, calls: int, rs274: bool = False) -> None:
    """Main O0001: rows of 100 pockets 1 mm apart; O0100 cuts one 0.8 mm square and steps
    X+1 mm (G91), then returns to G90 and M99."""
    w = Writer(path)
    body = ["G91 G01 Z-3. F3000.", "X0.8", "Y0.8", "X-0.8", "Y-0.8", "G00 Z3.", "X1.", "G90"]
    if rs274:
        w.line(f"(MAIN: {calls} SUBPROGRAM CALLS)")
        w.line("o100 sub")
        for b in body:
            w.line(b)
        w.line("o100 endsub")
        w.line("G90 G21 G17 G40 G49 G80 G54")
        w.line("G00 Z2.")
        for c in range(calls):
            if c % 100 == 0:
                w.line(f"G90 G00 X0. Y{num((c // 100) % 100 * 1.0)}")
            w.line("o100 call")
        w.line("G00 Z5.")
        w.line("M30")
        w.close()
        return
    w.line("%")
    w.line(f"O0001 (MAIN: {calls} SUBPROGRAM CALLS)")
    w.line("G90 G21 G17 G40 G49 G80 G54")
    w.line("G00 Z2.")
    for c in range(calls):
        if c % 100 == 0:
            w.line(f"G90 G00 X0. Y{num((c // 100) % 100 * 1.0)}")
        w.line("M98 P0100")
    w.line("G00 Z5.")
    w.line("M30")
    w.line("")
    w.line("O0100 (POCKET STEP)")
    for b in body:
        w.line(b)
    w.line("M99")
    w.line("%")
    w.close()


# ---------------------------------------------------------------------------------------------
def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdir", help="folder to write the programs into (created if missing)")
    ap.add_argument("--lines", type=int, default=1_000_000, help="G01 lines of linear_*.nc")
    ap.add_argument("--mixed", type=int, default=200_000, help="moves of mixed_*.nc")
    ap.add_argument("--iterations", type=int, default=1_000_000, help="WHILE iterations of while_*.nc")
    ap.add_argument("--calls", type=int, default=100_000, help="M98 calls of sub_*.nc")
    ap.add_argument("--only", default="linear,mixed,while,sub",
                    help="comma-separated subset of: linear, mixed, while, sub")
    ap.add_argument("--seed", type=int, default=1, help="random seed of the mixed workload")
    ap.add_argument("--dialect", choices=("fanuc", "rs274"), default="fanuc",
                    help="fanuc: .nc files for ncvm; rs274: the same workloads as .ngc for LinuxCNC")
    a = ap.parse_args()

    wanted = [s.strip() for s in a.only.split(",") if s.strip()]
    for s in wanted:
        if s not in ("linear", "mixed", "while", "sub"):
            ap.error(f"unknown workload {s!r}")
    for n in (a.lines, a.mixed, a.iterations, a.calls):
        if n < 1:
            ap.error("sizes must be positive")
    os.makedirs(a.outdir, exist_ok=True)

    rs = a.dialect == "rs274"
    ext = "ngc" if rs else "nc"
    jobs = {
        "linear": (f"linear_{size_tag(a.lines)}.{ext}", lambda p: gen_linear(p, a.lines, rs)),
        "mixed": (f"mixed_{size_tag(a.mixed)}.{ext}", lambda p: gen_mixed(p, a.mixed, a.seed, rs)),
        "while": (f"while_{size_tag(a.iterations)}.{ext}", lambda p: gen_while(p, a.iterations, rs)),
        "sub": (f"sub_{size_tag(a.calls)}.{ext}", lambda p: gen_sub(p, a.calls, rs)),
    }
    for key in wanted:
        name, fn = jobs[key]
        path = os.path.join(a.outdir, name)
        fn(path)
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
