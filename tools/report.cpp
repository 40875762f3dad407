#include "report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frontpack_tool {

// Each result struct's field list names every member once (frontpack/fields.hpp): a member added
// without its field stops the build here, before the JSON or Python could miss it.
static_assert(frontpack::fields_complete<frontpack::Certificate>());
static_assert(frontpack::fields_complete<frontpack::CertifyReport>());
static_assert(frontpack::fields_complete<frontpack::TargetReport>());
static_assert(frontpack::fields_complete<frontpack::Progress>());
static_assert(frontpack::fields_complete<frontpack::FillStats>());
static_assert(frontpack::fields_complete<frontpack::SizeClassRow>());
static_assert(frontpack::fields_complete<frontpack::HistogramBin>());
static_assert(frontpack::fields_complete<frontpack::SizeStats>());
static_assert(frontpack::fields_complete<frontpack::EmptyCircle>());
static_assert(frontpack::fields_complete<frontpack::HoleCount>());
static_assert(frontpack::fields_complete<frontpack::CoverageBin>());
static_assert(frontpack::fields_complete<frontpack::CellCoverage>());
static_assert(frontpack::fields_complete<frontpack::PackingStats>());

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string fmt4(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

Json domain_json(const std::string& source, const frontpack::Domain& domain) {
  Json j{{"source", source},
         {"area", domain.area()},
         {"polygons", domain.num_polygons()},
         {"holes", domain.num_holes()},
         {"vertices", domain.num_vertices()}};
  if (domain.periodicity() != frontpack::Periodicity::none) {
    j["periodicity"] = frontpack::to_string(domain.periodicity());
  }
  return j;
}

namespace {

// The summary's additions to the field lists' JSON (json_fields.hpp), each named here: the
// request's comparison only with a request; the largest empty circle only when computed, its
// centre also as "x" and "y" and its radius in rmax; each profile bin's ends in rmax; the cell
// map to 6 decimals (a cell of 8 rmax holds some 50 disks: its coverage is not known closer);
// without walls (a cell periodic in x and y) the band's figures null.
void adjust_sizes_json(Json& j, const frontpack::SizeStats& s) {
  if (!s.compared) {
    for (const char* key : {"requested", "ks_by_number", "ks_by_area", "ks_by_number_at", "ks_by_area_at"}) {
      j.erase(key);
    }
  }
}

void adjust_void_json(Json& j, const frontpack::PackingStats& s) {
  const frontpack::EmptyCircle& e = s.largest_empty_circle;
  if (e.computed) {
    Json& circle = j["largest_empty_circle"];
    circle["x"] = e.centre.x;
    circle["y"] = e.centre.y;
    circle["radius_over_rmax"] = s.sizes.rmax > 0 ? Json(e.radius / s.sizes.rmax) : Json(nullptr);
  } else {
    j.erase("largest_empty_circle");
  }
  Json& profile = j["coverage_profile"];
  for (std::size_t k = 0; k < s.coverage_profile.size(); ++k) {
    const frontpack::CoverageBin& b = s.coverage_profile[k];
    profile[k]["from_rmax"] = b.from / s.coverage_unit;
    profile[k]["to_rmax"] = b.to / s.coverage_unit;  // infinity, written null, for the last bin
  }
  Json map = Json::array();
  for (const double v : s.cell_coverage.map) {
    map.push_back(std::isnan(v) ? Json(nullptr) : Json(std::round(v * 1e6) / 1e6));
  }
  j["cell_coverage"]["map"] = std::move(map);
}

}  // namespace

Json stats_json(const frontpack::PackingStats& s) {
  Json j = fields_json(s);
  if (!s.walls) {
    for (const char* key : {"band_fraction", "band_fraction_error", "band_median_by_area", "segregation_ks_by_area"}) {
      j[key] = nullptr;
    }
  }
  adjust_sizes_json(j["radius"], s.sizes);
  adjust_void_json(j, s);
  return j;
}

Json certificate_json(const frontpack::Certificate& c) {
  Json j{{"certified", true}};
  j.update(fields_json(c));
  return j;
}

Json fill_stats_json(const frontpack::FillStats& stats, bool jam) {
  Json j = fields_json(stats);
  if (!jam) {
    j.erase("jam");
  }
  return j;
}

Json certify_json(const frontpack::CertifyReport& r) {
  Json j = fields_json(r);
  // The summary counts the disks outside and the pairs overlapping (`frontpack check --all` lists them).
  j["outside"] = r.outside.size();
  j["overlapping_pairs"] = r.overlapping.size();
  // A depth or a distance without its disks means nothing: the group goes with its optional.
  if (!r.deepest_overlap) {
    j.erase("deepest_overlap");
  }
  if (!r.farthest_outside) {
    j.erase("farthest_outside");
  }
  return j;
}

std::vector<std::string> void_lines(const frontpack::PackingStats& s) {
  std::vector<std::string> lines;
  const frontpack::EmptyCircle& e = s.largest_empty_circle;
  if (e.computed) {
    std::string line = "empty circle: radius " + fmt(e.radius) + " (<= " + fmt(e.radius_upper) + ")";
    if (s.sizes.rmax > 0) {
      line += ", " + fmt4(e.radius / s.sizes.rmax) + " rmax";
    }
    lines.push_back(line + ", at (" + fmt(e.centre.x) + ", " + fmt(e.centre.y) + ")");
  }
  if (!s.holes.empty()) {
    std::string line = "holes:        ";
    for (std::size_t k = 0; k < s.holes.size(); ++k) {
      line.append(k == 0 ? "" : ", ").append(std::to_string(s.holes[k].count));
      line.append(" taking radius ").append(fmt(s.holes[k].radius));
    }
    lines.push_back(line);
  }
  if (!s.coverage_profile.empty()) {
    std::string line = "profile:      ";
    for (std::size_t k = 0; k < s.coverage_profile.size(); ++k) {
      const frontpack::CoverageBin& b = s.coverage_profile[k];
      line.append(k == 0 ? "" : ", ")
          .append(b.samples == 0 ? std::string("none") : fmt4(b.fraction))
          .append(" at ")
          .append(fmt(b.from / s.coverage_unit));
      if (std::isinf(b.to)) {
        line.append("+");
      } else {
        line.append("-").append(fmt(b.to / s.coverage_unit));
      }
    }
    lines.push_back(line + " rmax from the boundary");
  }
  const frontpack::CellCoverage& c = s.cell_coverage;
  if (c.cells > 0) {
    lines.push_back("cells:        " + std::to_string(c.cells) + " interior cells of side " + fmt(c.cell_side) + " (" +
                    fmt(c.cell_side / s.sizes.rmax) + " rmax): coverage p1 " + fmt4(c.p1) + ", p5 " + fmt4(c.p5) +
                    ", median " + fmt4(c.p50) + ", sd " + fmt4(c.sd));
  }
  return lines;
}

std::string fraction_line(const frontpack::PackingStats& s) {
  std::string line = fmt4(s.packing_fraction);
  line.append(" overall");
  if (s.interior_samples > 0) {
    line.append(", ").append(fmt4(s.interior_fraction)).append(" interior (+/- ").append(fmt4(s.interior_error));
    line.append(s.walls ? ", farther than " + fmt(s.band_width) + " from the boundary)" : ", no walls)");
  }
  if (s.band_samples > 0) {
    line.append(", ").append(fmt4(s.band_fraction)).append(" in the band");
  }
  return line;
}

std::string radii_line(const frontpack::SizeStats& s) {
  if (s.count == 0) {
    return "none";
  }
  return std::string("min ") + fmt(s.rmin) + ", mean " + fmt(s.mean) + ", max " + fmt(s.rmax) + ", sd " + fmt(s.sd) +
         ", median by area " + fmt(s.median_area);
}

Json target_json(const frontpack::TargetReport& t) {
  Json j = fields_json(t);
  // What was not asked for is left out.
  if (!(t.fraction_requested > 0)) {
    for (const char* key : {"fraction_requested", "fraction_dense", "scale", "removed"}) {
      j.erase(key);
    }
  }
  if (t.count_requested == 0) {
    j.erase("count_requested");
    j.erase("count_achieved");
  }
  return j;
}

std::string target_line(const frontpack::TargetReport& t) {
  std::string line;
  if (t.fraction_requested > 0) {
    line = "fraction " + fmt4(t.fraction_requested) + " asked, " + fmt4(t.fraction_achieved) + " reached (dense " +
           fmt4(t.fraction_dense) + "; radii filled " + fmt4(t.scale) + "x then shrunk back, " +
           std::to_string(t.removed) + " disks thinned; " + std::to_string(t.fills) + " fills)";
  } else if (t.count_requested > 0) {
    line = "count " + std::to_string(t.count_requested) + " asked" +
           (t.count_achieved < t.count_requested
                ? ", " + std::to_string(t.count_achieved) + " placed: the domain holds no more at these radii"
                : "") +
           "; fraction " + fmt4(t.fraction_achieved) + " of the domain";
  } else {
    line = "fraction " + fmt4(t.fraction_achieved) + " of the area filled";
  }
  return t.height ? line + ", below y = " + fmt(*t.height) + " (area " + fmt(t.area_filled) + ")" : line;
}

}  // namespace frontpack_tool
