// frontpack.measure (stats.hpp): a packing's statistics as a dict of the PackingStats fields.
#include <pybind11/stl.h>

#include <optional>
#include <utility>

#include "bind.hpp"

namespace frontpack::python {

namespace {

py::dict sizes_dict(const SizeStats& s) {
  py::dict d;
  d["count"] = s.count;
  d["rmin"] = s.rmin;
  d["rmax"] = s.rmax;
  d["mean"] = s.mean;
  d["sd"] = s.sd;
  d["median_number"] = s.median_number;
  d["median_area"] = s.median_area;
  d["compared"] = s.compared;
  d["requested"] = s.requested;
  d["ks_number"] = s.ks_number;
  d["ks_area"] = s.ks_area;
  d["ks_number_at"] = s.ks_number_at;
  d["ks_area_at"] = s.ks_area_at;
  py::list classes;
  for (const SizeClassRow& r : s.classes) {
    py::dict c;
    c["radius"] = r.radius;
    c["requested_number"] = r.requested_number;
    c["requested_area"] = r.requested_area;
    c["achieved_number"] = r.achieved_number;
    c["achieved_area"] = r.achieved_area;
    c["requested_number_passing"] = r.requested_number_passing;
    c["requested_area_passing"] = r.requested_area_passing;
    c["achieved_number_passing"] = r.achieved_number_passing;
    c["achieved_area_passing"] = r.achieved_area_passing;
    classes.append(c);
  }
  d["classes"] = classes;
  py::list histogram;
  for (const HistogramBin& b : s.histogram) {
    py::dict h;
    h["lo"] = b.lo;
    h["hi"] = b.hi;
    h["count"] = b.count;
    h["achieved_number"] = b.achieved_number;
    h["achieved_area"] = b.achieved_area;
    h["requested_number"] = b.requested_number;
    h["requested_area"] = b.requested_area;
    histogram.append(h);
  }
  d["histogram"] = histogram;
  return d;
}

py::dict stats_dict(PackingStats&& s) {
  py::dict d;
  d["disks"] = s.disks;
  d["domain_area"] = s.domain_area;
  d["disk_area"] = s.disk_area;
  d["packing_fraction"] = s.packing_fraction;
  d["void_ratio"] = s.void_ratio;
  d["band_width"] = s.band_width;
  d["interior_fraction"] = s.interior_fraction;
  d["band_fraction"] = s.band_fraction;
  d["interior_error"] = s.interior_error;
  d["band_error"] = s.band_error;
  d["interior_area"] = s.interior_area;
  d["band_area"] = s.band_area;
  d["interior_samples"] = s.interior_samples;
  d["band_samples"] = s.band_samples;
  d["contact_gap"] = s.contact_gap;
  d["contacts"] = s.contacts;
  d["overlaps"] = s.overlaps;
  d["max_overlap"] = s.max_overlap;
  d["wall_contacts"] = s.wall_contacts;
  d["mean_coordination"] = s.mean_coordination;
  d["coordination_histogram"] = s.coordination_histogram;
  d["rattlers"] = s.rattlers;
  d["mean_coordination_without_rattlers"] = s.mean_coordination_without_rattlers;
  d["interior_disks"] = s.interior_disks;
  d["interior_coordination"] = s.interior_coordination;
  d["band_disks"] = s.band_disks;
  d["band_median_area"] = s.band_median_area;
  d["inside_median_area"] = s.inside_median_area;
  d["segregation_ks_area"] = s.segregation_ks_area;
  const EmptyCircle& e = s.largest_empty_circle;
  py::dict circle;
  circle["computed"] = e.computed;
  circle["radius"] = e.radius;
  circle["radius_upper"] = e.radius_upper;
  circle["centre"] = py::make_tuple(e.centre.x, e.centre.y);
  circle["tolerance"] = e.tolerance;
  d["largest_empty_circle"] = circle;
  py::dict holes;
  for (const HoleCount& h : s.holes) {
    holes[py::float_(h.radius)] = h.count;
  }
  d["holes"] = holes;
  d["coverage_unit"] = s.coverage_unit;
  py::list profile;
  for (const CoverageBin& b : s.coverage_profile) {
    py::dict p;
    p["from"] = b.from;
    p["to"] = b.to;
    p["fraction"] = b.fraction;
    p["error"] = b.error;
    p["samples"] = b.samples;
    profile.append(p);
  }
  d["coverage_profile"] = profile;
  py::dict cells;
  cells["cell_side"] = s.cell_coverage.cell_side;
  cells["cells"] = s.cell_coverage.cells;
  cells["p1"] = s.cell_coverage.p1;
  cells["p5"] = s.cell_coverage.p5;
  cells["p50"] = s.cell_coverage.p50;
  cells["sd"] = s.cell_coverage.sd;
  cells["origin"] = py::make_tuple(s.cell_coverage.origin.x, s.cell_coverage.origin.y);
  // (ny, nx): map[j, i] is the cell at origin + (i, j) cell_side, NaN outside the interior.
  cells["map"] = grid_array(std::move(s.cell_coverage.map), s.cell_coverage.ny, s.cell_coverage.nx);
  d["cell_coverage"] = cells;
  d["sizes"] = sizes_dict(s.sizes);
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
}

}  // namespace frontpack::python
