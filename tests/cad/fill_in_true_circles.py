#!/usr/bin/python3
"""`frontpack fill` on a drum DXF (tests/data/cad/drum.dxf: an outer CIRCLE and CIRCLE holes), then
every disk of the CSV checked, in exact rational arithmetic, against the TRUE circles as ezdxf
reads them from the DXF (not against frontpack's polygon): inside the largest circle, outside every
other one.

    fill_in_true_circles.py TOOL DXF OUT_DIR [--naive] [fill arguments...]

--naive fills instead a WKT polygon made the unsafe way (the wall's vertices outside it, the holes'
on them), to show that the check catches disks outside the true circles (ctest: WILL_FAIL).
Exit 0 when every disk passes, 1 otherwise, 77 (skipped) when ezdxf is missing, unless
FRONTPACK_REQUIRE_READERS=1 (tools/dev.sh test), where that fails too.
"""
import csv
import os
import subprocess
import sys
from fractions import Fraction

try:
    import ezdxf
except ImportError:
    print("python3-ezdxf is not installed")
    sys.exit(1 if os.environ.get("FRONTPACK_REQUIRE_READERS") == "1" else 77)

tool, dxf, out_dir, *fill_args = sys.argv[1:]
naive = fill_args[:1] == ["--naive"]
fill_args = fill_args[1:] if naive else fill_args
os.makedirs(out_dir, exist_ok=True)
out = os.path.join(out_dir, "drum.csv")
domain = dxf
if naive:
    import math
    cs = sorted(ezdxf.readfile(dxf).modelspace().query("CIRCLE"), key=lambda c: -c.dxf.radius)

    def ring(c, rho, n=32):
        pts = [(c.dxf.center.x + rho * math.cos(2 * math.pi * k / n), c.dxf.center.y + rho * math.sin(2 * math.pi * k / n))
               for k in range(n)]
        return "(" + ",".join("%r %r" % p for p in pts + pts[:1]) + ")"
    rings = [ring(cs[0], cs[0].dxf.radius / math.cos(math.pi / 32))] + [ring(c, c.dxf.radius) for c in cs[1:]]
    domain = os.path.join(out_dir, "naive.wkt")
    with open(domain, "w") as f:
        f.write("POLYGON(" + ",".join(rings) + ")\n")
run = subprocess.run([tool, "fill", domain, "-o", out, *fill_args], capture_output=True, text=True)
print(run.stderr)
if run.returncode != 0 or "certified: " not in run.stderr or " 0 dropped" not in run.stderr:
    print("fill failed or was not certified without repair (exit %d)" % run.returncode)
    sys.exit(1)

circles = [(Fraction(c.dxf.center.x), Fraction(c.dxf.center.y), Fraction(c.dxf.radius))
           for c in ezdxf.readfile(dxf).modelspace().query("CIRCLE")]
circles.sort(key=lambda c: -c[2])
outer, holes = circles[0], circles[1:]

with open(out) as f:
    rows = list(csv.DictReader(f))
if len(rows) < 100:
    print("only %d disks" % len(rows))
    sys.exit(1)
bad = 0
for row in rows:
    x, y, r = (Fraction(float(row[k])) for k in ("x", "y", "r"))
    cx, cy, R = outer
    d2 = (x - cx) ** 2 + (y - cy) ** 2
    if R - r < 0 or d2 > (R - r) ** 2:
        bad += 1
        print("disk %s leaves the outer circle" % row)
    for cx, cy, R in holes:
        if (x - cx) ** 2 + (y - cy) ** 2 < (R + r) ** 2:
            bad += 1
            print("disk %s enters the hole about (%s %s)" % (row, float(cx), float(cy)))
print("%d disks, %d outside the true circles (%d holes)" % (len(rows), bad, len(holes)))
sys.exit(1 if bad else 0)
