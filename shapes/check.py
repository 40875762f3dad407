#!/usr/bin/env python3
"""Optional developer check of the bundled sample domains (needs shapely).

    /usr/bin/python3 shapes/check.py        # Debian: apt-get install python3-shapely

For every shapes/*.wkt file: parses it, checks OGC validity (GEOS is_valid),
checks that the text round-trips exactly through IEEE doubles, reports ring
orientations, and prints parts / holes / vertices / bbox / area.  The
generator (generate.py) does NOT depend on this script or on shapely.

Vertex counts exclude the repeated closing point of each ring.
"""

import glob
import os
import re
import sys

from shapely import wkt
from shapely.validation import explain_validity

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # keep shapes/ free of __pycache__
sys.path.insert(0, HERE)
from generate import fmt  # noqa: E402  (the generator's number formatter)


def polygons(g):
    return list(g.geoms) if g.geom_type == "MultiPolygon" else [g]


def main():
    ok = True
    rows = []
    for path in sorted(glob.glob(os.path.join(HERE, "*.wkt"))):
        name = os.path.basename(path)
        text = open(path, encoding="ascii").read()
        g = wkt.loads(text)
        # exact round trip: every literal must be the repr of the double it parses to
        # (written as the shortest fixed-point decimal of its double, no exponent)
        for tok in re.findall(r"-?[0-9.]+(?:[eE][-+]?[0-9]+)?", text):
            if tok != fmt(float(tok)):
                ok = False
                print("%s: literal %s is not the shortest round-trip form" % (name, tok))
        polys = polygons(g)
        holes = sum(len(p.interiors) for p in polys)
        verts = sum(len(p.exterior.coords) - 1 + sum(len(r.coords) - 1 for r in p.interiors)
                    for p in polys)
        orient = []
        for p in polys:
            o = "ccw" if p.exterior.is_ccw else "CW"
            hs = set("cw" if not r.is_ccw else "CCW" for r in p.interiors)
            orient.append(o + ("/" + ",".join(sorted(hs)) if hs else ""))
        valid = g.is_valid
        if not valid:
            ok = False
        b = g.bounds
        rows.append((name, g.geom_type, len(polys), holes, verts, b, g.area, valid,
                     explain_validity(g), " ".join(sorted(set(orient))), len(text)))
    for (name, gt, parts, holes, verts, b, area, valid, why, orient, size) in rows:
        print("%-22s %-12s parts=%d holes=%d verts=%d bbox=(%.12g %.12g, %.12g %.12g) "
              "area=%.12g valid=%s orient=%s bytes=%d"
              % (name, gt, parts, holes, verts, b[0], b[1], b[2], b[3], area, valid, orient, size))
        if not valid:
            print("    ", why)
    print("ALL VALID" if ok else "PROBLEMS FOUND")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
