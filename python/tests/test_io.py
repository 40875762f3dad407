"""Writers and readers for every format (bit-exact round trips), pictures, types, decks, and
certify()/measure() on arrays from elsewhere."""

import math
import os
import subprocess

import numpy as np
import pytest

import frontpack
from conftest import need, same_bits

DOMAIN = "POLYGON((0 0,1 0,1 1,0 1,0 0),(0.3 0.3,0.3 0.5,0.5 0.5,0.5 0.3,0.3 0.3))"


@pytest.fixture(scope="module")
def packing():
    p = frontpack.fill(DOMAIN, "lognormal:0.02,1.4", seed=11)
    assert len(p) > 200
    return p


@pytest.mark.parametrize("extension,format", [
    ("csv", "csv"), ("yade", "yade"), ("txt", "yade"), ("data", "lammps"), ("lmp", "lammps"), ("vtp", "vtp"),
])
def test_round_trip_is_bit_exact(tmp_path, packing, extension, format):
    path = tmp_path / ("disks." + extension)
    frontpack.write(path, DOMAIN, packing.disks)
    assert same_bits(frontpack.read_disks(path), packing.disks)
    assert same_bits(frontpack.read_disks(str(path), format), packing.disks)
    assert path.read_text() == frontpack.dumps(DOMAIN, packing.disks, format)


def test_round_trip_of_awkward_numbers(tmp_path):
    disks = np.array([[0.1, 1 / 3, 5e-324], [-2.5e-300, 1e300, 0.30000000000000004], [-0.0, 7.0, 1.0]])
    for name in ("a.csv", "a.yade", "a.vtp"):
        frontpack.write(tmp_path / name, DOMAIN, disks)
        assert same_bits(frontpack.read_disks(tmp_path / name), disks)


def test_lammps_dump_reader(tmp_path):
    dump = tmp_path / "run.lammpstrj"
    snapshot = "ITEM: TIMESTEP\n{t}\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff pp\n0 1\n0 1\n-1 1\n" \
               "ITEM: ATOMS id type x y z radius\n2 1 0.75 0.5 0 0.125\n1 1 0.25 {y} 0 0.125\n"
    dump.write_text(snapshot.format(t=0, y=0.5) + snapshot.format(t=100, y=0.625))
    last = frontpack.read_disks(dump)
    assert last.tolist() == [[0.25, 0.625, 0.125], [0.75, 0.5, 0.125]]
    first = frontpack.read_disks(dump, "lammps-dump", timestep=0)
    assert first[0].tolist() == [0.25, 0.5, 0.125]
    with pytest.raises(frontpack.DiskFileError) as e:
        frontpack.read_disks(dump, timestep=50)
    assert e.value.kind == "missing_item"


def test_types_are_carried(tmp_path, packing):
    types = frontpack.assign_types("size:0.02", packing.disks)
    assert types.dtype == np.uint32 and set(types.tolist()) == {1, 2}
    assert (types == np.where(packing.disks[:, 2] >= 0.02, 2, 1)).all()
    assert (frontpack.assign_types([0.02], packing.disks) == types).all()
    text = frontpack.dumps(DOMAIN, packing.disks, "csv", types=types)
    assert text.startswith("x,y,r,type\n")
    assert text.splitlines()[1].endswith(",%d" % types[0])
    data = frontpack.dumps(DOMAIN, packing.disks, "lammps", types=types, type_densities=[2500, 7800])
    assert "2 atom types" in data
    with pytest.raises(ValueError, match="types must be"):
        frontpack.dumps(DOMAIN, packing.disks, "csv", types=[[1]])


def test_svg_render(tmp_path, packing):
    path = tmp_path / "p.svg"
    frontpack.render(path, DOMAIN, packing.disks, width=300)
    text = path.read_text()
    assert "<svg" in text and text.count("<circle") == len(packing)
    assert frontpack.dumps(DOMAIN, packing.disks, "svg", width=300) == text


def test_writer_errors(tmp_path, packing):
    with pytest.raises(frontpack.OptionError, match=r"\.png"):
        frontpack.write(tmp_path / "p.png", DOMAIN, packing.disks)
    target = tmp_path / "no" / "such" / "dir.csv"
    with pytest.raises(frontpack.IoError) as e:
        frontpack.write(target, DOMAIN, packing.disks)
    assert e.value.path == str(target)
    with pytest.raises(frontpack.OptionError):
        frontpack.dumps(DOMAIN, packing.disks, "lammps", density=-1)


@pytest.mark.parametrize("bad", [(0.5, 0.5, -0.1), (0.5, 0.5, 0.0), (0.5, 0.5, math.inf), (0.5, 0.5, math.nan),
                                 (math.nan, 0.5, 0.1), (0.5, -math.inf, 0.1)])
@pytest.mark.parametrize("extension", ["csv", "txt", "data", "vtp", "svg"])
def test_every_writer_refuses_a_disk_with_bad_values(tmp_path, bad, extension):
    disks = np.array([(0.25, 0.25, 0.1), bad])
    path = tmp_path / ("p." + extension)
    with pytest.raises(frontpack.OptionError, match=r"disk 1 \(centre .*\) is not a disk"):
        frontpack.write(path, DOMAIN, disks)
    assert not path.exists() and os.listdir(tmp_path) == []
    with pytest.raises(frontpack.OptionError, match=r"disk 1 "):
        frontpack.dumps(DOMAIN, disks, "yade" if extension == "txt" else
                        "lammps" if extension == "data" else extension)


def test_disk_file_error_fields(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y,r\n0.5,0.5,0.1\n0.5,abc,0.1\n")
    with pytest.raises(frontpack.DiskFileError) as e:
        frontpack.read_disks(bad)
    err = e.value
    assert isinstance(err, ValueError)
    assert (err.kind, err.line, err.column) == ("bad_number", 3, 5)
    assert err.source == str(bad) and str(err).startswith("%s:3:5: " % bad)


def test_certify_finds_a_planted_overlap_and_a_disk_outside(packing):
    disks = packing.disks.copy()
    assert frontpack.certify(DOMAIN, disks).valid
    x, y, r = disks[4]
    disks[9] = (x + r, y, r)  # overlaps disk 4 (and maybe others)
    disks[20] = (0.4, 0.4, 0.01)  # in the hole
    report = frontpack.certify(DOMAIN, disks)
    assert not report
    assert report.overlapping.dtype == np.int64 and report.overlapping.shape[1] == 2
    assert [4, 9] in report.overlapping.tolist()
    assert (report.overlapping[:, 0] < report.overlapping[:, 1]).all()
    assert 20 in report.outside.tolist() and report.outside.dtype == np.int64
    assert report.deepest_overlap is not None and report.deepest_overlap_depth > 0
    # touching is not overlapping: exactly tangent in binary (x + 2r exact)
    tangent = np.array([[0.125, 0.125, 0.0625], [0.25, 0.125, 0.0625]])
    assert frontpack.certify(DOMAIN, tangent).valid


def test_certify_accepts_any_array_like():
    assert frontpack.certify(DOMAIN, [[0.1, 0.1, 0.05]]).valid
    assert frontpack.certify(DOMAIN, np.empty((0, 3))).valid
    assert frontpack.certify(DOMAIN, []).valid
    report = frontpack.certify(DOMAIN, np.array([[0.1, 0.1, np.nan]], dtype=np.float32))
    assert report.outside.tolist() == [0]
    with pytest.raises(ValueError, match=r"shape \(N, 3\), not \(2, 2\)"):
        frontpack.certify(DOMAIN, [[1, 2], [3, 4]])


def test_measure(packing):
    s = frontpack.measure(DOMAIN, packing.disks, requested=frontpack.Radii("lognormal:0.02,1.4"), samples=20000)
    disk_area = math.fsum(math.pi * r * r for r in packing.disks[:, 2])
    assert s["disks"] == len(packing)
    assert s["packing_fraction"] == pytest.approx(disk_area / 0.96, rel=1e-12)
    assert 0.6 < s["packing_fraction"] < 0.9
    assert s["overlaps"] == 0 and s["mean_coordination"] > 2
    assert s["sizes"]["compared"] and s["sizes"]["ks_area"] < 0.2
    assert len(s["holes"]) == 2 and s["largest_empty_circle"]["computed"]
    with pytest.raises(ValueError, match="disk"):
        frontpack.measure(DOMAIN, [[0.1, 0.1, -1.0]])


def test_cell_coverage_map():
    # A square lattice of disks of radius r, spacing 2 r, in a square of 64 r (r a power of two:
    # the cells of 8 r tile it exactly): each cell covers pi / 4; one disk taken out of the cell
    # at column 2, row 3 shows there alone.
    r = 1 / 64
    # (lattice disk (9, 13), centre (19 r, 27 r), lies wholly in the cell [16 r, 24 r] x [24 r, 32 r])
    disks = [[(2 * i + 1) * r, (2 * j + 1) * r, r] for j in range(32) for i in range(32) if (i, j) != (9, 13)]
    assert len(disks) == 32 * 32 - 1
    s = frontpack.measure("POLYGON((0 0,1 0,1 1,0 1,0 0))", disks, samples=0)["cell_coverage"]
    assert s["origin"] == (0.0, 0.0) and s["cell_side"] == 8 * r
    grid = s["map"]
    assert grid.shape == (8, 8) and grid.dtype == np.float64
    interior = ~np.isnan(grid)
    assert interior.sum() == s["cells"] == 36  # the outer ring of cells comes within 2 r of a wall
    low = np.argwhere(grid < math.pi / 4 - 1e-9)
    assert low.tolist() == [[3, 2]]  # map[j, i]
    assert grid[3, 2] == pytest.approx(math.pi / 4 * 15 / 16, abs=1e-12)
    assert s["p1"] == grid[3, 2]
    # Cells of 16 r: 4 across, the inner 2 x 2 interior; the one at (1, 1) holds the gap.
    s = frontpack.measure("POLYGON((0 0,1 0,1 1,0 1,0 0))", disks, samples=0, cell_side=16 * r)["cell_coverage"]
    assert s["cell_side"] == 16 * r and s["map"].shape == (4, 4) and s["cells"] == 4
    assert np.argwhere(s["map"] < math.pi / 4 - 1e-9).tolist() == [[1, 1]]
    assert s["map"][1, 1] == pytest.approx(math.pi / 4 * 63 / 64, abs=1e-12)


def test_render_cells(tmp_path):
    # The lattice of test_cell_coverage_map drawn by `frontpack render --cells` at 300 px (a margin
    # of 6 px, 288 px to the unit, cells of 36 px): the cell with the gap darkest, the other
    # interior cells lightest, the outer ring of cells the domain's grey.
    matplotlib_image = need("matplotlib.image")
    tool = os.environ.get("FRONTPACK_TOOL")
    if not tool:
        pytest.skip("FRONTPACK_TOOL is not set (the build has no tool)")
    r = 1 / 64
    disks = [[(2 * i + 1) * r, (2 * j + 1) * r, r] for j in range(32) for i in range(32) if (i, j) != (9, 13)]
    frontpack.write(tmp_path / "d.csv", "POLYGON((0 0,1 0,1 1,0 1,0 0))", disks)
    (tmp_path / "sq.wkt").write_text("POLYGON((0 0,1 0,1 1,0 1,0 0))\n")
    out = subprocess.run([tool, "render", str(tmp_path / "sq.wkt"), str(tmp_path / "d.csv"), "--cells", "--width",
                          "300", "-o", str(tmp_path / "c.png")], capture_output=True, text=True, check=True)
    assert "36 interior cells of side 0.125, coverage 0.7363 (dark) to 0.7854 (light)" in out.stderr
    img = matplotlib_image.imread(tmp_path / "c.png")
    assert img.shape[:2] == (300, 300)

    def cell(i, j):  # the pixel at the centre of cell (i, j), as 0-255 RGB
        return tuple(round(255 * v) for v in img[300 - 6 - round((j + 0.5) * 36), 6 + round((i + 0.5) * 36)][:3])

    assert cell(2, 3) == (68, 1, 84)  # viridis at 0
    for i in range(1, 7):
        for j in range(1, 7):
            if (i, j) != (2, 3):
                assert cell(i, j) == (253, 231, 37), (i, j)  # viridis at 1
    assert cell(0, 0) == cell(7, 7) == (230, 230, 230)

    # --cells-range: the gap's cell (pi / 4 * 15 / 16 = 0.73631) halfway from 0.70 to 0.77262, so
    # viridis at 0.5; the others (pi / 4 = 0.78540) beyond the light end, so viridis at 1.
    out = subprocess.run([tool, "render", str(tmp_path / "sq.wkt"), str(tmp_path / "d.csv"), "--cells",
                          "--cells-range=0.70,0.77262", "--width", "300", "-o", str(tmp_path / "c.png")],
                         capture_output=True, text=True, check=True)
    assert "coverage 0.7000 (dark) to 0.7726 (light), the cells' 0.7363 to 0.7854" in out.stderr
    img = matplotlib_image.imread(tmp_path / "c.png")
    assert cell(2, 3) == (38, 130, 142)  # viridis at 0.5
    assert cell(5, 5) == cell(1, 6) == (253, 231, 37)


def test_deck_and_wall_disks(packing):
    walls = frontpack.wall_disks(DOMAIN, 0.01, 0.01)
    assert walls.shape[1] == 3 and len(walls) > 100
    assert not frontpack.as_domain(DOMAIN).contains(walls).any()
    deck = frontpack.make_deck(DOMAIN, packing.disks, "lammps", densities=[2500])
    assert "in.frontpack" in deck and "read_data" in deck["in.frontpack"]


def test_measure_holds_hole_probes_to_the_budget():
    # A hole radius a millionth of the disks' asks for about 10^9 squares: refused up front with
    # the figure, by count and by memory; a radius within the budget is counted.
    disks = [[0.25, 0.25, 0.125], [0.5, 0.25, 0.125], [0.75, 0.75, 0.125], [0.25, 0.75, 0.125]]
    with pytest.raises(frontpack.LimitError, match=r"about [0-9.e+]+ hole probes, more than max_disks = 50000000"):
        frontpack.measure("POLYGON((0 0,1 0,1 1,0 1,0 0))", disks, samples=0, hole_radii=[1e-6])
    with pytest.raises(frontpack.LimitError, match=r"hole probes, needing about .* more than the limit of 1048576 bytes"):
        frontpack.measure("POLYGON((0 0,1 0,1 1,0 1,0 0))", disks, samples=0, hole_radii=[1e-4], memory_limit=1 << 20)
    s = frontpack.measure("POLYGON((0 0,1 0,1 1,0 1,0 0))", disks, samples=0, hole_radii=[1e-3], max_disks=10_000_000)
    assert list(s["holes"].values())[0] >= 1
