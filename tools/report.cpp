#include "report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frontpack_tool {

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

Json sizes_json(const frontpack::SizeStats& s) {
  Json j{{"count", s.count},
         {"min", s.rmin},
         {"max", s.rmax},
         {"mean", s.mean},
         {"sd", s.sd},
         {"median_by_number", s.median_number},
         {"median_by_area", s.median_area}};
  if (s.compared) {
    j["requested"] = s.requested;
    j["ks_by_number"] = s.ks_number;
    j["ks_by_area"] = s.ks_area;
  }
  return j;
}

void add_void_json(Json& j, const frontpack::PackingStats& s) {
  const frontpack::EmptyCircle& e = s.largest_empty_circle;
  if (e.computed) {
    j["largest_empty_circle"] =
        Json{{"radius", e.radius},
             {"radius_upper", e.radius_upper},
             {"x", e.centre.x},
             {"y", e.centre.y},
             {"radius_over_rmax", s.sizes.rmax > 0 ? Json(e.radius / s.sizes.rmax) : Json(nullptr)}};
  }
  Json holes = Json::array();
  for (const frontpack::HoleCount& h : s.holes) {
    holes.push_back(Json{{"radius", h.radius}, {"count", h.count}});
  }
  j["holes"] = holes;
  Json profile = Json::array();
  for (const frontpack::CoverageBin& b : s.coverage_profile) {
    const bool last = std::isinf(b.to);
    profile.push_back(Json{{"from", b.from},
                           {"to", last ? Json(nullptr) : Json(b.to)},
                           {"from_rmax", b.from / s.coverage_unit},
                           {"to_rmax", last ? Json(nullptr) : Json(b.to / s.coverage_unit)},
                           {"fraction", b.fraction},
                           {"error", b.error},
                           {"samples", b.samples}});
  }
  j["coverage_profile"] = profile;
  const frontpack::CellCoverage& c = s.cell_coverage;
  // The map row by row from below, null where a cell is not wholly in the interior, each value
  // to 6 decimals (a cell of 8 rmax holds some 50 disks: its coverage is not known closer).
  Json map = Json::array();
  for (const double v : c.map) {
    map.push_back(std::isnan(v) ? Json(nullptr) : Json(std::round(v * 1e6) / 1e6));
  }
  j["cell_coverage"] = Json{{"cell_side", c.cell_side},
                            {"cells", c.cells},
                            {"p1", c.p1},
                            {"p5", c.p5},
                            {"p50", c.p50},
                            {"sd", c.sd},
                            {"origin", Json::array({c.origin.x, c.origin.y})},
                            {"nx", c.nx},
                            {"ny", c.ny},
                            {"map", std::move(map)}};
}

}  // namespace

Json stats_json(const frontpack::PackingStats& s) {
  // Without walls (a cell periodic in x and y) there is no band: its figures are null.
  const auto band = [&s](double v) { return s.walls ? Json(v) : Json(nullptr); };
  Json j{{"packing_fraction", s.packing_fraction},
         {"interior_fraction", s.interior_fraction},
         {"interior_fraction_error", s.interior_error},
         {"walls", s.walls},
         {"band_fraction", band(s.band_fraction)},
         {"band_fraction_error", band(s.band_error)},
         {"band_width", s.band_width},
         {"void_ratio", std::isfinite(s.void_ratio) ? Json(s.void_ratio) : Json(nullptr)},
         {"mean_coordination", s.mean_coordination},
         {"interior_coordination", s.interior_coordination},
         {"contacts", s.contacts},
         {"wall_contacts", s.wall_contacts},
         {"rattlers", s.rattlers},
         {"contact_gap", s.contact_gap},
         {"band_disks", s.band_disks},
         {"band_median_by_area", band(s.band_median_area)},
         {"inside_median_by_area", s.inside_median_area},
         {"segregation_ks_by_area", band(s.segregation_ks_area)},
         {"radius", sizes_json(s.sizes)}};
  add_void_json(j, s);
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
  Json j{{"fraction_achieved", t.fraction_achieved}, {"area_filled", t.area_filled}, {"fills", t.fills}};
  if (t.fraction_requested > 0) {
    j["fraction_requested"] = t.fraction_requested;
    j["fraction_dense"] = t.fraction_dense;
    j["scale"] = t.scale;
    j["removed"] = t.removed;
  }
  if (t.count_requested > 0) {
    j["count_requested"] = t.count_requested;
    j["count_achieved"] = t.count_achieved;
  }
  if (t.height) {
    j["height"] = *t.height;
  }
  j["outside_original"] = t.outside_original;
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
