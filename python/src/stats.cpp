// frontpack.measure (stats.hpp): a packing's statistics as a dict of the PackingStats fields.
#include <pybind11/stl.h>

#include <optional>
#include <utility>

#include "bind.hpp"
#include "fields.hpp"

namespace frontpack::python {

namespace {

// The dict of every PackingStats field (fields.hpp), with two kinds of its own: the holes as
// {radius: count}, and the cell map as an (ny, nx) array, map[j, i] the cell at origin + (i, j)
// cell_side, NaN outside the interior.
py::dict stats_dict(PackingStats&& s) {
  py::dict d = fields_dict(s);
  py::dict holes;
  for (const HoleCount& h : s.holes) {
    holes[py::float_(h.radius)] = h.count;
  }
  d["holes"] = holes;
  py::dict cells = d["cell_coverage"];
  cells["map"] = grid_array(std::move(s.cell_coverage.map), s.cell_coverage.ny, s.cell_coverage.nx);
  return d;
}

}  // namespace

void bind_stats(py::module_& m) {
  m.def(
      "measure",
      [](const Domain& domain, const py::handle& disks, const std::optional<Radii>& requested, double contact_gap,
         double band_width, std::size_t samples, std::size_t histogram_bins, bool contacts, bool empty_circle,
         bool holes, const std::vector<double>& hole_radii, bool coverage_profile, bool cell_coverage, double cell_side,
         std::size_t max_disks, std::size_t memory_limit) {
        const std::vector<Disk> ds = disks_from(disks);
        StatsOptions o;
        o.requested = requested;
        o.contact_gap = contact_gap;
        o.band_width = band_width;
        o.samples = samples;
        o.histogram_bins = histogram_bins;
        o.contacts = contacts;
        o.empty_circle = empty_circle;
        o.holes = holes;
        o.hole_radii = hole_radii;
        o.coverage_profile = coverage_profile;
        o.cell_coverage = cell_coverage;
        o.cell_side = cell_side;
        o.budget = {.max_count = max_disks, .memory_limit = memory_limit};
        PackingStats s;
        {
          py::gil_scoped_release release;
          s = measure(domain, ds, o);
        }
        return stats_dict(std::move(s));
      },
      py::arg("domain"), py::arg("disks"), py::kw_only(), py::arg("requested") = py::none(),
      py::arg("contact_gap") = 0.0, py::arg("band_width") = 0.0, py::arg("samples") = std::size_t{1'000'000},
      py::arg("histogram_bins") = std::size_t{20}, py::arg("contacts") = true, py::arg("empty_circle") = true,
      py::arg("holes") = true, py::arg("hole_radii") = std::vector<double>{}, py::arg("coverage_profile") = true,
      py::arg("cell_coverage") = true, py::arg("cell_side") = 0.0, py::arg("max_disks") = Budget{}.max_count,
      py::arg("memory_limit") = Budget{}.memory_limit,
      "The statistics a DEM user checks a packing by (stats.hpp; docs/distributions.md has the definitions), as "
      "a dict: packing_fraction, void_ratio, interior_fraction and band_fraction (sampled, with their binomial "
      "standard errors), contacts, mean_coordination, rattlers, wall_contacts, segregation_ks_area, "
      "largest_empty_circle, holes ({radius: count}), coverage_profile, cell_coverage, and sizes (against "
      "`requested`, a Radii). Disks must have finite centres and radii > 0 (else ValueError naming the disk). "
      "0 for contact_gap, band_width and cell_side means automatic (cell_side: 8 rmax). What measuring makes "
      "(sample points, hole probes, coverage cells, periodic images) is estimated first and held to max_disks "
      "and memory_limit (bytes; 0: three quarters of the memory), as fill's disks are: LimitError. Deterministic.");

  // For python/tests/test_result_fields.py: each result struct's field names, in order, from the
  // field lists the attributes, the dicts and the stubs must follow.
  m.def("_result_fields", [] {
    py::dict listing;
    list_fields<Certificate>(listing, "Certificate");
    list_fields<CertifyReport>(listing, "CertifyReport");
    list_fields<Progress>(listing, "Progress");
    list_fields<FillStats>(listing, "FillStats");
    list_fields<TargetReport>(listing, "TargetReport");
    list_fields<PackingStats>(listing, "PackingStats");
    list_fields<SizeStats>(listing, "SizeStats");
    list_fields<SizeClassRow>(listing, "SizeClassRow");
    list_fields<HistogramBin>(listing, "HistogramBin");
    list_fields<EmptyCircle>(listing, "EmptyCircle");
    list_fields<HoleCount>(listing, "HoleCount");
    list_fields<CoverageBin>(listing, "CoverageBin");
    list_fields<CellCoverage>(listing, "CellCoverage");
    return listing;
  });
}

}  // namespace frontpack::python
