#!/usr/bin/python3
"""Makes the CAD and GIS test fixtures of tests/data/cad/ with well-known writers: ezdxf
(python3-ezdxf) for DXF, GDAL's ogr2ogr (gdal-bin) for GeoJSON and Shapefile.

Run from anywhere with /usr/bin/python3 tests/data/cad/make_fixtures.py; it rewrites the files
beside it. tests/cad_test.cpp states what each file must read to.
"""
import os
import subprocess
import tempfile

import ezdxf

HERE = os.path.dirname(os.path.abspath(__file__))


def new_doc():
    doc = ezdxf.new("R2010")
    return doc, doc.modelspace()


def save(doc, name):
    doc.saveas(os.path.join(HERE, name))


# A drum: outer wall CIRCLE r = 1 with a pipe (CIRCLE hole r = 0.25), centres off the grid so
# that the polylines' rounding is not trivial. Plus a dimension, which is skipped.
doc, msp = new_doc()
msp.add_circle((10.1, 20.3), 1.0)
msp.add_circle((10.4, 20.4), 0.25)
msp.add_text("drum", dxfattribs={"height": 0.1}).set_placement((9.5, 21.5))
save(doc, "drum.dxf")

# A plate (area 2 + pi/8 - pi/32 - pi/25): an LWPOLYLINE rectangle 2 x 1 with bulges: bulge 1 on
# (2,0)->(2,1), a convex half-disk end of radius 0.5 (chords); bulge -1 on (0.25,0)->(0.75,0), a
# clockwise half circle of radius 0.25 that cuts a notch into the plate (tangents). The hole is
# drawn the CAD way: two vertices, bulge 1 each (a circle of radius 0.2 about (0.5, 0.5)).
doc, msp = new_doc()
msp.add_lwpolyline(
    [(0, 0, 0), (0.25, 0, -1.0), (0.75, 0, 0), (2, 0, 1.0), (2, 1, 0), (0, 1, 0)],
    format="xyb", close=True)
msp.add_lwpolyline([(0.3, 0.5, 1.0), (0.7, 0.5, 1.0)], format="xyb", close=True)
save(doc, "bulge_plate.dxf")

# A stadium of LINE and ARC entities, joined end to end: the left ARC is written anticlockwise as
# usual, the right one with the extrusion direction (0, 0, -1) (its centre and angles in the
# mirrored object coordinate system), as some CAD programs write them.
doc, msp = new_doc()
msp.add_line((0, 0), (2, 0))
msp.add_line((2, 1), (0, 1))
msp.add_arc((0, 0.5), 0.5, 90, 270)
msp.add_arc((-2, 0.5), 0.5, 90, 270, dxfattribs={"extrusion": (0, 0, -1)})
save(doc, "line_arc.dxf")

# An island in a hole: three nested circles (depths 0, 1, 2: two polygons, one hole).
doc, msp = new_doc()
for r in (3.0, 2.0, 1.0):
    msp.add_circle((0, 0), r)
save(doc, "nested.dxf")

# Many pipes far from the origin: a CIRCLE of radius 50 about (1e5 + 0.1, -3e4 + 0.7) with 40
# CIRCLE holes of awkward radii, where rounding puts vertices on the wrong side of their circle
# unless they are moved back.
doc, msp = new_doc()
cx, cy = 1e5 + 0.1, -3e4 + 0.7
msp.add_circle((cx, cy), 50.0)
for i in range(8):
    for j in range(5):
        msp.add_circle((cx - 35 + 10 * i + 0.013 * j, cy - 20 + 10 * j + 0.007 * i), 1.0 + 0.1 * i + 0.0123 * j)
save(doc, "many_pipes.dxf")

# A nearly flat arc far from the origin: a unit square at (1e4, 1e4) whose top edge has bulge
# -1e-6, a notch of sagitta 5e-7 on a circle of radius about 2.5e5 (tangents: the vertex between the
# end tangents must be placed from the chord, not from the far centre).
doc, msp = new_doc()
x0, y0 = 1e4, 1e4
msp.add_lwpolyline([(x0, y0, 0), (x0 + 1, y0, 0), (x0 + 1, y0 + 1, -1e-6), (x0, y0 + 1, 0)], format="xyb", close=True)
save(doc, "flat_bulge.dxf")

# Errors.
doc, msp = new_doc()
msp.add_lwpolyline([(0, 0), (1, 0), (1, 1)], close=False)
save(doc, "open_polyline.dxf")
doc, msp = new_doc()
msp.add_line((0, 0), (2, 0))
msp.add_line((2, 1), (0, 1))
msp.add_arc((0, 0.5), 0.5, 90, 270)
save(doc, "open_chain.dxf")
doc, msp = new_doc()
msp.add_circle((0, 0), 1.0)
msp.add_ellipse((0, 0), (0.5, 0), 0.5)
save(doc, "ellipse.dxf")
doc, msp = new_doc()
msp.add_circle((0, 0), 1.0)
msp.add_circle((1.5, 0), 1.0)
save(doc, "crossing.dxf")
doc, msp = new_doc()
msp.add_text("nothing here")
save(doc, "empty.dxf")
doc, msp = new_doc()
msp.add_circle((0, 0), 0.0)
save(doc, "zero_radius.dxf")
doc, msp = new_doc()
msp.add_line((0, 0), (1, 0))
msp.add_line((1, 0), (1, 1))
msp.add_line((1, 1), (0, 0))
msp.add_line((1, 0), (2, 0))
msp.add_line((2, 0), (1, 1))
save(doc, "branching.dxf")


def ogr(out_name, driver, wkts, extra=()):
    with tempfile.TemporaryDirectory() as tmp:
        csv = os.path.join(tmp, "input.csv")
        with open(csv, "w") as f:
            f.write("id,WKT\n")
            for i, w in enumerate(wkts):
                f.write('%d,"%s"\n' % (i, w))
        out = os.path.join(HERE, out_name)
        stem = os.path.splitext(out)[0]
        for ext in (".geojson", ".shp", ".shx", ".dbf", ".prj", ".cpg"):
            if os.path.exists(stem + ext) and (ext == os.path.splitext(out)[1] or driver == "ESRI Shapefile"):
                os.remove(stem + ext)
        subprocess.run(["ogr2ogr", "-f", driver, out, csv, "-nln", os.path.splitext(out_name)[0], "-select", "id",
                        *extra], check=True)


# A GeoJSON polygon with a hole (area 4 - 1 = 3), and a shapefile with one multipolygon of two
# squares, one with a hole (area 1 + 4 - 0.25 = 4.75).
ogr("plate.geojson", "GeoJSON", ["POLYGON((0 0,2 0,2 2,0 2,0 0),(0.5 0.5,0.5 1.5,1.5 1.5,1.5 0.5,0.5 0.5))"])
ogr("islands.shp", "ESRI Shapefile",
    ["MULTIPOLYGON(((0 0,1 0,1 1,0 1,0 0)),((3 0,5 0,5 2,3 2,3 0),(3.5 0.5,3.5 1,4 1,4 0.5,3.5 0.5)))"],
    ["-nlt", "MULTIPOLYGON"])
ogr("points.geojson", "GeoJSON", ["POINT(1 2)"])
