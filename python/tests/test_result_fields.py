"""Every field of every result struct reaches Python and the stubs: the attribute classes
(Certificate, CertifyReport, Progress, FillStats) and the dicts (a fill's target, measure()'s
statistics and their parts) hold one attribute or key per field of the C++ field lists
(include/frontpack/fields.hpp), which _core._result_fields lists, and __init__.pyi declares them in
the same order. A member added to a struct without its field fails to compile
(tests/result_fields_test.cpp); a field the module or the stubs miss fails here."""

import ast
import pathlib

import numpy as np
import pytest

import frontpack

FIELDS = frontpack._core._result_fields()
CLASSES = ("Certificate", "CertifyReport", "Progress", "FillStats")
DICTS = (
    "TargetReport",
    "PackingStats",
    "SizeStats",
    "SizeClassRow",
    "HistogramBin",
    "EmptyCircle",
    "CoverageBin",
    "CellCoverage",
)
SQUARE = "POLYGON((0 0, 1 0, 1 1, 0 1, 0 0))"


def stub_fields():
    """{name: [declared fields, in order]} of the stub's classes and TypedDicts."""
    tree = ast.parse((pathlib.Path(frontpack.__file__).parent / "__init__.pyi").read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = [m.target.id for m in node.body if isinstance(m, ast.AnnAssign)]
        elif isinstance(node, ast.Assign) and isinstance(node.value, ast.Call):
            if getattr(node.value.func, "id", "") == "TypedDict":
                out[node.targets[0].id] = [k.value for k in node.value.args[1].keys]
    return out


def test_the_listing_covers_every_result_struct():
    assert sorted(FIELDS) == sorted(CLASSES + DICTS + ("HoleCount",))
    assert all(len(names) == len(set(names)) > 0 for names in FIELDS.values())


@pytest.mark.parametrize("name", CLASSES + DICTS)
def test_the_stubs_declare_every_field_in_order(name):
    assert stub_fields()[name] == FIELDS[name]


@pytest.mark.parametrize("name", CLASSES)
def test_classes_bind_every_field_with_its_doc(name):
    cls = getattr(frontpack, name)
    for field in FIELDS[name]:
        assert hasattr(cls, field), (name, field)
        assert (getattr(cls, field).__doc__ or "").strip(), (name, field)


def test_progress_phase_names_jam():
    assert "'jam'" in frontpack.Progress.phase.__doc__


def test_a_jammed_fill_reaches_every_field():
    seen = []
    packing = frontpack.fill(
        SQUARE, "discrete:0.04:0.5,0.056:0.5", jam=True, seed=2, progress=lambda p: seen.append(p) or True
    )
    assert {p.phase for p in seen} == {"generate", "certify", "jam"}
    for p in seen[:3]:
        assert [type(getattr(p, f)) for f in FIELDS["Progress"]] == [int, float, float, str]
    stats = packing.stats
    assert [f for f in FIELDS["FillStats"] if not hasattr(stats, f)] == []
    assert stats.jam_rounds > 0 and stats.jam_steps > 0 and stats.seconds_jam > 0
    assert all(getattr(packing.certificate, f) is not None for f in FIELDS["Certificate"])
    assert packing.target is None


def test_a_target_dict_has_every_field():
    packing = frontpack.fill(SQUARE, 0.05, method="open", count=20, height=0.5)
    assert list(packing.target) == FIELDS["TargetReport"]
    assert packing.target["count_achieved"] == 20 and packing.target["height"] == 0.5


def test_a_certify_report_reaches_every_field():
    report = frontpack.certify(SQUARE, np.array([[0.5, 0.5, 0.1], [0.55, 0.5, 0.1], [2.0, 2.0, 0.1]]))
    values = {f: getattr(report, f) for f in FIELDS["CertifyReport"]}
    assert values["outside"].tolist() == [2] and values["overlapping"].tolist() == [[0, 1]]
    assert values["deepest_overlap"] == (0, 1) and values["farthest_outside"] == 2
    assert values["deepest_overlap_depth"] > 0 and values["farthest_outside_by"] > 0
    assert isinstance(values["certificate"], frontpack.Certificate)


def test_measure_dicts_have_every_field():
    requested = frontpack.Radii.discrete([(0.04, 0.5), (0.056, 0.5)])
    packing = frontpack.fill(SQUARE, requested, seed=3)
    s = frontpack.measure(SQUARE, packing.disks, requested=requested, samples=20_000)
    assert list(s) == FIELDS["PackingStats"]
    assert list(s["sizes"]) == FIELDS["SizeStats"]
    assert s["sizes"]["compared"] and s["sizes"]["classes"] and s["sizes"]["histogram"]
    assert list(s["sizes"]["classes"][0]) == FIELDS["SizeClassRow"]
    assert list(s["sizes"]["histogram"][0]) == FIELDS["HistogramBin"]
    assert list(s["largest_empty_circle"]) == FIELDS["EmptyCircle"]
    assert s["coverage_profile"] and list(s["coverage_profile"][0]) == FIELDS["CoverageBin"]
    assert list(s["cell_coverage"]) == FIELDS["CellCoverage"]
    assert s["cell_coverage"]["map"].shape == (s["cell_coverage"]["ny"], s["cell_coverage"]["nx"])
    # HoleCount's two fields as the dict {radius: count}.
    assert FIELDS["HoleCount"] == ["radius", "count"]
    assert s["holes"] and all(isinstance(r, float) and isinstance(n, int) for r, n in s["holes"].items())
