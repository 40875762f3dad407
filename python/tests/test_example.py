"""examples/python_fill.py runs and writes what it says: a LAMMPS file of certified disks, a picture."""

import os
import pathlib
import subprocess
import sys

import frontpack
from conftest import ROOT, need


def test_example_script(tmp_path):
    need("shapely")
    matplotlib = os.environ.get("FRONTPACK_REQUIRE_READERS") == "1" and need("matplotlib")
    script = ROOT / "examples" / "python_fill.py"
    run = subprocess.run([sys.executable, str(script), str(tmp_path)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "disks, certified" in run.stdout
    disks = frontpack.read_disks(tmp_path / "plate.data")
    plate = "POLYGON((0 0,0.2 0,0.2 0.1,0 0.1,0 0))"
    assert len(disks) > 500 and frontpack.certify(plate, disks).outside.size == 0
    assert frontpack.certify(plate, disks).overlapping.size == 0
    if matplotlib or (tmp_path / "plate.png").exists():
        assert (tmp_path / "plate.png").read_bytes().startswith(b"\x89PNG")
    assert pathlib.Path(tmp_path / "plate.data").read_text().count("\n") > len(disks)
