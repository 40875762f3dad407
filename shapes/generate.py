#!/usr/bin/env python3
"""Generate the bundled sample domains of frontpack (shapes/*.wkt).

Python 3 standard library only.  Running

    python3 shapes/generate.py

(from the repository root, or from anywhere else) rewrites every *.wkt file
in the directory of this script.  The output is deterministic: all random
numbers come from random.Random(20031), and every coordinate is written as
the shortest fixed-point decimal that parses back to exactly the same
IEEE-754 double, so the files round-trip exactly and regenerate
byte-identically.

Conventions of the written files:
  * one geometry (POLYGON or MULTIPOLYGON, 2D) per file, followed by "\n";
  * rings are closed (last point repeats the first one);
  * outer rings anticlockwise and holes clockwise, EXCEPT l_shape.wkt, whose
    outer ring is deliberately clockwise to exercise the loader's
    orientation normalisation.
"""

import math
import os
import random

OUT_DIR = os.path.dirname(os.path.abspath(__file__))

SEED = 20031
SIG_DIGITS = 12  # computed (irrational) coordinates are rounded to 12 significant digits


# ---------------------------------------------------------------------------
# number formatting and ring helpers
# ---------------------------------------------------------------------------

def q(x):
    """Quantise a computed coordinate to SIG_DIGITS significant digits."""
    x = float("%.*g" % (SIG_DIGITS, x))
    if x == 0.0:
        x = 0.0  # drop the sign of -0.0
    return x


def fmt(x):
    """Shortest fixed-point (no exponent) decimal that round-trips to x exactly."""
    x = float(x)
    if x == 0.0:
        return "0"
    if x == int(x) and abs(x) < 2.0 ** 53:
        return str(int(x))
    s = repr(x)
    if "e" not in s and "E" not in s:
        if s.endswith(".0"):
            s = s[:-2]
        return s
    for d in range(1, 400):
        s = "%.*f" % (d, x)
        if float(s) == x:
            s = s.rstrip("0").rstrip(".")
            return s
    raise ValueError("cannot format %r" % x)


def signed_area(ring):
    """Shoelace signed area of an open ring (positive = anticlockwise)."""
    a = 0.0
    n = len(ring)
    for i in range(n):
        x0, y0 = ring[i]
        x1, y1 = ring[(i + 1) % n]
        a += x0 * y1 - x1 * y0
    return 0.5 * a


def oriented(ring, ccw):
    """Return the open ring with the requested orientation."""
    ring = list(ring)
    if (signed_area(ring) > 0.0) != ccw:
        ring = [ring[0]] + ring[:0:-1]
    return ring


def ring_text(ring):
    ring = list(ring)
    assert len(ring) >= 3
    assert ring[0] != ring[-1], "rings are given open and closed here"
    pts = ring + [ring[0]]
    return "(" + ",".join(fmt(x) + " " + fmt(y) for x, y in pts) + ")"


def polygon_body(shell, holes=(), shell_ccw=True):
    rings = [oriented(shell, shell_ccw)] + [oriented(h, False) for h in holes]
    return "(" + ",".join(ring_text(r) for r in rings) + ")"


def polygon_wkt(shell, holes=(), shell_ccw=True):
    return "POLYGON" + polygon_body(shell, holes, shell_ccw)


def multipolygon_wkt(parts):
    """parts: list of (shell, holes)."""
    return "MULTIPOLYGON(" + ",".join(polygon_body(s, h) for s, h in parts) + ")"


def circle(cx, cy, r, n, phase=0.0):
    """Regular n-gon inscribed in the circle (cx, cy, r), anticlockwise."""
    pts = []
    for k in range(n):
        t = phase + 2.0 * math.pi * k / n
        pts.append((q(cx + r * math.cos(t)), q(cy + r * math.sin(t))))
    return pts


def is_strictly_convex_ccw(ring):
    n = len(ring)
    for i in range(n):
        ax, ay = ring[i - 1]
        bx, by = ring[i]
        cx, cy = ring[(i + 1) % n]
        if (bx - ax) * (cy - by) - (by - ay) * (cx - bx) <= 0.0:
            return False
    return True


# ---------------------------------------------------------------------------
# the shapes
# ---------------------------------------------------------------------------

def unit_square():
    # Written literally, anticlockwise, exactly as specified.
    return "POLYGON((0 0,1 0,1 1,0 1,0 0))"


CONVEX = [(0.1, 0), (0.7, 0.05), (1, 0.35), (0.95, 0.8), (0.55, 1), (0.1, 0.85), (0, 0.4)]


def convex_polygon():
    # Irregular convex heptagon in [0,1]^2, in the spirit of Fig. 11(a) of
    # Feng, Han & Owen (2003).
    assert is_strictly_convex_ccw(CONVEX)
    return polygon_wkt(CONVEX)


# Irregular polygon with three deep notches (reflex corners at (0.5, 0.45),
# (0.55, 0.6) and (0.25, 0.6)), in the spirit of Fig. 11(b) of Feng, Han &
# Owen (2003).  All coordinates are multiples of 0.05.
CONCAVE = [
    (0, 0.1), (0.35, 0), (0.5, 0.45), (0.65, 0), (1, 0.05), (0.95, 0.45),
    (0.55, 0.6), (1, 0.7), (0.9, 1), (0.4, 0.95), (0.25, 0.6), (0.05, 0.8),
]


def concave_polygon():
    return polygon_wkt(CONCAVE)


def l_shape():
    # 2x2 square minus the upper-right 1x1 quadrant.  Outer ring CLOCKWISE on
    # purpose (exercises orientation normalisation in the loader).
    shell = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    return polygon_wkt(shell, shell_ccw=False)


PLATE_HOLES = [  # (cx, cy, r)
    (0.6, 0.6, 0.3),
    (1.5, 1.3, 0.4),
    (2.5, 0.6, 0.25),
    (3.3, 1.35, 0.35),
    (0.7, 1.5, 0.2),
    (3.4, 0.45, 0.15),
    (2.3, 1.55, 0.12),
]


def plate_with_holes():
    shell = [(0, 0), (4, 0), (4, 2), (0, 2)]
    holes = []
    for cx, cy, r in PLATE_HOLES:
        n = 96 if r >= 0.35 else (64 if r >= 0.25 else 48)
        holes.append(circle(cx, cy, r, n))
    return polygon_wkt(shell, holes)


def annulus():
    return polygon_wkt(circle(0, 0, 1, 256), [circle(0, 0, 0.5, 128)])


def islands():
    # A: unit square with a hexagonal hole.
    a_shell = [(0, 0), (1, 0), (1, 1), (0, 1)]
    a_hole = circle(0.5, 0.5, 0.25, 6)
    # B: a triangle.
    b_shell = [(1.5, 0), (2.5, 0.2), (1.8, 1)]
    # C: a disk (64-gon).
    c_shell = circle(1.2, 1.8, 0.4, 64)
    # D: a small L.
    d_shell = [(2.2, 1.3), (3, 1.3), (3, 1.6), (2.5, 1.6), (2.5, 2.2), (2.2, 2.2)]
    return multipolygon_wkt([
        (a_shell, [a_hole]),
        (b_shell, []),
        (c_shell, []),
        (d_shell, []),
    ])


def gear():
    # 16 teeth; each pitch: sharp V-shaped root (reflex corner) at radius 0.7,
    # a flat tooth tip at radius 1; central bore of radius 0.25.
    teeth = 16
    pitch = 2.0 * math.pi / teeth
    shell = []
    for i in range(teeth):
        t0 = i * pitch
        for t, r in ((t0, 0.7), (t0 + 0.35 * pitch, 1.0), (t0 + 0.65 * pitch, 1.0)):
            shell.append((q(r * math.cos(t)), q(r * math.sin(t))))
    bore = circle(0, 0, 0.25, 64)
    return polygon_wkt(shell, [bore])


def narrow_channel():
    # Two 1x1 chambers joined by a channel of length 1 and width 0.05.
    shell = [
        (0, 0), (1, 0), (1, 0.475), (2, 0.475), (2, 0), (3, 0),
        (3, 1), (2, 1), (2, 0.525), (1, 0.525), (1, 1), (0, 1),
    ]
    return polygon_wkt(shell)


def comb():
    # Spine 1.7 x 0.25 with 9 teeth of width 0.1 and length 1, gaps 0.1.
    teeth = 9
    w = 0.1
    spine = 0.25
    top = 1.25
    width = round((2 * teeth - 1) * w, 9)
    shell = [(0, 0), (width, 0)]
    # walk right to left along the top edge
    for k in range(teeth - 1, -1, -1):
        x0 = round(2 * k * w, 9)
        x1 = round(x0 + w, 9)
        shell.append((x1, top))
        shell.append((x0, top))
        if k > 0:
            shell.append((x0, spine))
            shell.append((round(x0 - w, 9), spine))
    return polygon_wkt(shell)


def big_polygon(rng):
    # Star-shaped outer ring with 12000 vertices: strictly increasing angles
    # and a positive, noisy radius r(theta) make it simple by construction.
    n = 12000
    r0 = 10.0
    modes = []
    for k in range(2, 41):
        amp = rng.uniform(0.3, 1.0) * 0.12 / k
        modes.append((k, amp, rng.uniform(0.0, 2.0 * math.pi)))
    # sum of |amplitudes| <= 0.12 * (H_40 - 1) < 0.42 -> r >= 10*(1 - 0.42) - 0.003 > 5.7
    # (the per-vertex radial jitter of +-0.003 is comparable to the ~0.005
    # vertex spacing, so the ring is rough but has no needle-like spikes)
    step = 2.0 * math.pi / n
    shell = []
    for i in range(n):
        t = (i + rng.uniform(-0.3, 0.3)) * step
        r = 1.0 + sum(a * math.cos(k * t + ph) for k, a, ph in modes)
        r = r0 * r + rng.uniform(-0.003, 0.003)
        assert r > 5.7
        shell.append((q(r * math.cos(t)), q(r * math.sin(t))))
    holes = []
    # 1: a noisy 40-gon around (4, 0), radius <= 1.2
    hole = []
    for i in range(40):
        t = 2.0 * math.pi * i / 40
        r = rng.uniform(0.8, 1.2)
        hole.append((q(4 + r * math.cos(t)), q(r * math.sin(t))))
    holes.append(hole)
    # 2: a regular 24-gon around (-2, 3.5), radius 1
    holes.append(circle(-2, 3.5, 1.0, 24))
    # 3: a rotated square around (-2, -3.5)
    holes.append(circle(-2, -3.5, 1.1, 4, phase=0.3))
    # 4: a five-pointed star around (0, 0)
    star = []
    for i in range(10):
        t = math.pi / 2 + math.pi * i / 5
        r = 1.2 if i % 2 == 0 else 0.5
        star.append((q(r * math.cos(t)), q(r * math.sin(t))))
    holes.append(star)
    return polygon_wkt(shell, holes)


OFFSET = 1000000


def offset_1e6():
    # The concave polygon scaled by 100 (integer coordinates) and translated
    # by (1e6, 1e6), with a small rectangular hole with dyadic coordinates.
    # Every coordinate is exactly representable, so the translation is exact.
    shell = [(OFFSET + round(100 * x), OFFSET + round(100 * y)) for x, y in CONCAVE]
    hole = [(OFFSET + 60.5, OFFSET + 70.25), (OFFSET + 80.75, OFFSET + 70.25),
            (OFFSET + 80.75, OFFSET + 85.5), (OFFSET + 60.5, OFFSET + 85.5)]
    return polygon_wkt(shell, [hole])


def millimetre():
    # 1 mm x 1 mm square (SI units: metres) with a central hole of radius 0.25 mm.
    shell = [(0, 0), (0.001, 0), (0.001, 0.001), (0, 0.001)]
    return polygon_wkt(shell, [circle(0.0005, 0.0005, 0.00025, 64)])


def hole_touching():
    # Triangular hole touching the outer ring at the single point (2, 0).
    shell = [(0, 0), (4, 0), (4, 4), (0, 4)]
    hole = [(2, 0), (3, 2), (1, 2)]
    return polygon_wkt(shell, [hole])


def main():
    rng = random.Random(SEED)
    shapes = [
        ("unit_square.wkt", unit_square()),
        ("convex_polygon.wkt", convex_polygon()),
        ("concave_polygon.wkt", concave_polygon()),
        ("l_shape.wkt", l_shape()),
        ("plate_with_holes.wkt", plate_with_holes()),
        ("annulus.wkt", annulus()),
        ("islands.wkt", islands()),
        ("gear.wkt", gear()),
        ("narrow_channel.wkt", narrow_channel()),
        ("comb.wkt", comb()),
        ("big_polygon.wkt", big_polygon(rng)),
        ("offset_1e6.wkt", offset_1e6()),
        ("millimetre.wkt", millimetre()),
        ("hole_touching.wkt", hole_touching()),
    ]
    for name, text in shapes:
        path = os.path.join(OUT_DIR, name)
        with open(path, "w", encoding="ascii", newline="\n") as f:
            f.write(text + "\n")
        print("wrote %s (%d bytes)" % (os.path.relpath(path), len(text) + 1))


if __name__ == "__main__":
    main()
