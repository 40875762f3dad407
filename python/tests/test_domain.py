"""frontpack.Domain: constructors from WKT, files, arrays and shapely; exact queries."""

import pickle

import numpy as np
import pytest

import frontpack
from conftest import need

SQUARE = "POLYGON((0 0,2 0,2 1,0 1,0 0))"


def test_from_wkt_properties():
    d = frontpack.Domain.from_wkt(SQUARE)
    assert d.area == 2.0
    assert d.bbox == (0.0, 0.0, 2.0, 1.0)
    assert (d.num_polygons, d.num_holes, d.num_vertices) == (1, 0, 4)
    assert d.periodicity == "none"
    assert frontpack.Domain.from_wkt(d.to_wkt()).to_wkt() == d.to_wkt()
    assert d.wkt == d.to_wkt()
    assert "area 2.0" in repr(d)


def test_locate_one_and_many():
    d = frontpack.Domain.from_wkt(SQUARE)
    assert d.locate((1, 0.5)) == frontpack.Location.inside
    assert d.locate((2, 0.5)) == frontpack.Location.boundary
    assert d.locate([3.0, 0.5]) == frontpack.Location.outside
    out = d.locate(np.array([[1, 0.5], [2, 0.5], [3, 0.5]]))
    assert out.dtype == np.uint8 and out.tolist() == [2, 1, 0]


def test_contains_vectorised_agrees_with_single():
    d = frontpack.Domain.from_wkt(SQUARE)
    rng = np.random.default_rng(1)
    disks = np.column_stack([rng.uniform(-0.5, 2.5, 500), rng.uniform(-0.5, 1.5, 500), rng.uniform(0, 0.3, 500)])
    disks[0] = (1.0, 0.5, 0.5)  # touches top and bottom: inside (closed)
    disks[1] = (1.0, 0.5, np.nan)
    many = d.contains(disks)
    assert many.dtype == np.bool_ and many.shape == (500,)
    assert many.tolist() == [d.contains(k) for k in disks]
    assert many[0] and not many[1]
    # the definition: inside iff the disk's box is within the rectangle (a convex box domain)
    x, y, r = disks[2:].T
    assert many[2:].tolist() == ((x - r >= 0) & (x + r <= 2) & (y - r >= 0) & (y + r <= 1)).tolist()


def test_from_rings_and_polygons():
    outer = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=float)
    hole = [(1, 1), (1, 2), (2, 2), (2, 1), (1, 1)]  # closed and clockwise or not: either
    d = frontpack.Domain.from_rings(outer, [hole])
    assert d.area == 15.0 and d.num_holes == 1
    (out_ring, holes), = d.polygons()
    assert out_ring.shape == (4, 2) and holes[0].shape == (4, 2)
    m = frontpack.Domain.from_polygons([(outer, [hole]), (outer + 10, [])])
    assert m.num_polygons == 2 and m.area == 31.0
    with pytest.raises(ValueError, match=r"shape \(N, 2\)"):
        frontpack.Domain.from_rings(np.zeros((4, 3)))


def test_from_file(shapes):
    d = frontpack.Domain.from_file(shapes / "concave_polygon.wkt")
    assert d.area == 0.6875
    assert frontpack.as_domain(shapes / "concave_polygon.wkt").area == 0.6875
    report = frontpack.read_domain_file(str(shapes / "annulus.wkt"))
    assert report["format"] == "wkt" and report["domain"].num_holes == 1


def test_shapely_polygon_with_hole(square_with_hole):
    d = frontpack.as_domain(square_with_hole)
    assert d.area == square_with_hole.area == 0.96
    assert d.num_holes == 1
    shapely_geometry = need("shapely.geometry")
    back = shapely_geometry.shape(d)  # Domain.__geo_interface__
    assert back.equals(square_with_hole)
    assert frontpack.Domain.from_shape(square_with_hole.__geo_interface__).area == 0.96


def test_shapely_multipolygon():
    geometry = need("shapely.geometry")
    mp = geometry.MultiPolygon([geometry.box(0, 0, 1, 1), geometry.box(2, 0, 3, 2)])
    d = frontpack.as_domain(mp)
    assert d.num_polygons == 2 and d.area == 3.0
    assert geometry.shape(d).equals(mp)


def test_object_with_wkt_only():
    class Shape:
        wkt = SQUARE

    assert frontpack.as_domain(Shape()).area == 2.0
    with pytest.raises(TypeError, match="cannot make a frontpack.Domain from int"):
        frontpack.as_domain(3)
    with pytest.raises(TypeError, match="not a 'Point' geometry"):
        frontpack.as_domain({"type": "Point", "coordinates": (0, 0)})


def test_periodic_cell():
    d = frontpack.Domain.periodic((0, 0, 2, 1), "x")
    assert d.periodicity == "x" and d.area == 2.0
    assert "periodic x" in repr(d)
    with pytest.raises(frontpack.OptionError):
        frontpack.Domain.periodic((0, 0, 2, 1), "none")
    with pytest.raises(frontpack.InvalidDomainError):
        frontpack.Domain.periodic((0, 0, 0, 1))
    # (LX, LY), as the tool's --periodic LX,LY: the cell [0, LX) x [0, LY).
    assert frontpack.Domain.periodic([1, 1]).bbox == (0.0, 0.0, 1.0, 1.0)
    assert frontpack.Domain.periodic((2, 1), "x").bbox == frontpack.Domain.periodic((0, 0, 2, 1), "x").bbox
    with pytest.raises(ValueError, match=r"\(LX, LY\) or \(xmin, ymin, xmax, ymax\): 2 or 4 numbers, not 3"):
        frontpack.Domain.periodic((1, 2, 3))


def test_wkt_error_fields():
    with pytest.raises(frontpack.WktError) as e:
        frontpack.Domain.from_wkt("POLYGON((0 0,1 0,1 1,0 0)")
    err = e.value
    assert isinstance(err, frontpack.Error) and isinstance(err, ValueError)
    assert (err.kind, err.line, err.column, err.offset) == ("syntax", 1, 26, 25)
    assert err.detail.startswith("expected ',' or ')'")
    assert str(err).startswith("WKT error at line 1, column 26")
    with pytest.raises(frontpack.WktError) as e:
        frontpack.Domain.from_wkt("POINT(1 2)")
    assert e.value.kind == "unsupported_geometry"


def test_invalid_domain_error_fields():
    with pytest.raises(frontpack.InvalidDomainError) as e:
        frontpack.Domain.from_wkt("POLYGON((0 0,1 1,1 0,0 1,0 0))")
    err = e.value
    assert err.kind == "self_intersection"
    assert err.site == (0, 0, 0) and err.other_site == (0, 0, 2)
    assert err.where == (0.5, 0.5)
    assert "cross" in str(err)


def test_io_error_fields(tmp_path):
    missing = tmp_path / "missing.wkt"
    with pytest.raises(frontpack.IoError) as e:
        frontpack.Domain.from_file(missing)
    assert isinstance(e.value, OSError)
    assert e.value.path == str(missing)
    assert "No such file or directory" in str(e.value)


def test_domain_file_error_fields(test_data):
    if not frontpack.has_dxf_reader():
        pytest.skip("this build reads no DXF")
    with pytest.raises(frontpack.DomainFileError) as e:
        frontpack.Domain.from_file(test_data / "cad" / "open_chain.dxf")
    err = e.value
    assert err.kind == "open_contour"
    assert err.source.endswith("open_chain.dxf") and "line" in err.entity
    assert str(err) == "%s: %s: %s" % (err.source, err.entity, err.detail)


def test_dxf_units_and_truncation(test_data, tmp_path):
    if not frontpack.has_dxf_reader():
        pytest.skip("this build reads no DXF")
    assert frontpack.read_domain_file(test_data / "cad" / "drum.dxf")["units"] == "meters"
    assert frontpack.read_domain_file(str(test_data / "cad" / "drum.dxf"), "auto")["format"] == "dxf"
    lines = (test_data / "cad" / "drum.dxf").read_text().splitlines(keepends=True)
    cut = tmp_path / "cut.dxf"
    cut.write_text("".join(lines[:-2]))  # without its EOF group
    with pytest.raises(frontpack.DomainFileError) as e:
        frontpack.Domain.from_file(cut)
    assert e.value.kind == "truncated"
    assert "the file ends before EOF, at line %d" % (len(lines) - 2) in str(e.value)


def test_pickle_round_trip():
    d = frontpack.Domain.from_wkt("POLYGON((0 0,1 0,1 1,0 1,0 0),(0.1 0.1,0.1 0.2,0.3 0.1,0.1 0.1))")
    back = pickle.loads(pickle.dumps(d))
    assert back.to_wkt() == d.to_wkt() and back.area == d.area
    cell = frontpack.Domain.periodic((0.1, -1, 2.3, 1), "x")
    back = pickle.loads(pickle.dumps(cell))
    assert back.periodicity == "x" and back.bbox == cell.bbox == (0.1, -1.0, 2.3, 1.0)
