#include "frontpack/domain.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "common/format.hpp"
#include "common/read_file.hpp"
#include "domain/edge_grid.hpp"
#include "domain/ring_set.hpp"
#include "domain/wkt_reader.hpp"
#include "periodic/cell.hpp"

namespace frontpack {

struct Domain::Impl {
  detail::RingSet rings;  // input order and orientation; the grid points into it
  detail::EdgeGrid grid;
  std::vector<Polygon> polygons;  // normalised
  std::vector<Box> polygon_boxes;
  std::size_t holes = 0;
  double area = 0.0;
  double perimeter = 0.0;
  double max_abs = 0.0;
  Periodicity periodicity = Periodicity::none;
  Box cell;  // the periodic cell (periodicity != none)

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

namespace {

std::shared_ptr<Domain::Impl> build(const detail::RawParts& parts, bool require_closed,
                                    const detail::SourceLocator& where) {
  auto impl = std::make_shared<Domain::Impl>();
  impl->rings = detail::make_ring_set(parts, require_closed, where);
  detail::validate(impl->rings, impl->grid, where);

  const detail::RingSet& rs = impl->rings;
  impl->area = detail::exact_domain_area(rs);
  impl->polygons.resize(rs.part_first_ring.size() - 1);
  impl->polygon_boxes.resize(impl->polygons.size());
  for (std::size_t r = 0; r < rs.rings.size(); ++r) {
    const detail::RingInfo& info = rs.rings[r];
    Ring ring(rs.v.begin() + info.first, rs.v.begin() + info.first + info.count);
    const bool outer = info.ring == 0;
    const int turn = detail::ring_orientation(rs, r);
    if ((turn > 0) != outer) {
      // Keep the first vertex first: reverse the rest.
      std::reverse(ring.begin() + 1, ring.end());
    }
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Point a = ring[k];
      const Point b = ring[(k + 1) % ring.size()];
      impl->perimeter += std::hypot(b.x - a.x, b.y - a.y);
      impl->max_abs = std::max({impl->max_abs, std::abs(a.x), std::abs(a.y)});
      impl->polygon_boxes[info.part].extend(a);
    }
    Polygon& polygon = impl->polygons[info.part];
    if (outer) {
      polygon.outer = std::move(ring);
    } else {
      polygon.holes.push_back(std::move(ring));
      ++impl->holes;
    }
  }
  return impl;
}

// Parses and validates WKT text; `source_name` (a file name, or empty) goes into the messages.
std::shared_ptr<const Domain::Impl> from_wkt_text(std::string_view text, const std::string& source_name) {
  std::vector<detail::ParsedPolygon> parsed;
  try {
    parsed = detail::parse_wkt(text);
  } catch (const WktError& e) {
    if (source_name.empty()) {
      throw;
    }
    throw WktError(e.kind(), e.detail(), e.offset(), e.line(), e.column(), source_name);
  }
  detail::RawParts parts(parsed.size());
  for (std::size_t p = 0; p < parsed.size(); ++p) {
    for (const auto& ring : parsed[p].rings) {
      parts[p].push_back(ring.points);
    }
  }
  const detail::SourceLocator where = [&](std::size_t p, std::size_t r, std::size_t k) -> std::string {
    if (p >= parsed.size() || r >= parsed[p].rings.size() || k >= parsed[p].rings[r].offsets.size()) {
      return {};
    }
    const detail::TextPosition pos = detail::text_position(text, parsed[p].rings[r].offsets[k]);
    return " (" + (source_name.empty() ? std::string() : source_name + ":") + "line " + std::to_string(pos.line) +
           ", column " + std::to_string(pos.column) + ")";
  };
  return build(parts, true, where);
}

void append_ring(std::string& out, const Ring& ring) {
  out += '(';
  for (std::size_t k = 0; k <= ring.size(); ++k) {
    const Point p = ring[k % ring.size()];
    if (k > 0) {
      out += ", ";
    }
    out += detail::format_double(p.x);
    out += ' ';
    out += detail::format_double(p.y);
  }
  out += ')';
}

}  // namespace

Domain::Domain(std::shared_ptr<const Impl> impl) noexcept : impl_(std::move(impl)) {}

Domain Domain::from_wkt(std::string_view wkt) {
  return Domain(from_wkt_text(wkt, {}));
}

Domain Domain::from_wkt_file(const std::filesystem::path& path) {
  const std::string text = detail::read_text_file(path);
  return Domain(from_wkt_text(text, path.string()));
}

Domain Domain::from_polygons(std::vector<Polygon> polygons) {
  detail::RawParts parts(polygons.size());
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    parts[p].push_back(std::move(polygons[p].outer));
    for (Ring& hole : polygons[p].holes) {
      parts[p].push_back(std::move(hole));
    }
  }
  return Domain(build(parts, false, {}));
}

Domain Domain::from_rings(Ring outer, std::vector<Ring> holes) {
  std::vector<Polygon> polygons(1);
  polygons[0].outer = std::move(outer);
  polygons[0].holes = std::move(holes);
  return from_polygons(std::move(polygons));
}

Domain Domain::periodic(const Box& cell, Periodicity axes) {
  if (axes == Periodicity::none) {
    throw OptionError("a periodic cell must be periodic in x (Periodicity::x) or in x and y (Periodicity::xy)");
  }
  using Kind = InvalidDomainError::Kind;
  const InvalidDomainError::Site site{};
  // (Appended piece by piece: GCC 12 warns falsely, -Wrestrict, on "[" + std::string&&.)
  std::string box = "periodic cell [";
  box += detail::format_double(cell.xmin);
  box += ", " + detail::format_double(cell.xmax) + ") x [";
  box += detail::format_double(cell.ymin);
  box += ", " + detail::format_double(cell.ymax) + ")";
  for (const double v : {cell.xmin, cell.ymin, cell.xmax, cell.ymax}) {
    if (!std::isfinite(v)) {
      throw InvalidDomainError(Kind::non_finite_coordinate, box + ": a bound is not finite", site);
    }
    if (std::abs(v) > max_coordinate) {
      throw InvalidDomainError(Kind::coordinate_out_of_range,
                               box + ": a bound is beyond " + detail::format_double(max_coordinate), site);
    }
  }
  // The periods are exact differences; their rounded values (which the generator uses) must be
  // positive and finite.
  if (!(cell.xmax - cell.xmin > 0) || !(cell.ymax - cell.ymin > 0)) {
    throw InvalidDomainError(Kind::zero_area, box + ": empty (each maximum must exceed its minimum)", site);
  }
  detail::RawParts parts(1);
  parts[0].push_back(
      Ring{{cell.xmin, cell.ymin}, {cell.xmax, cell.ymin}, {cell.xmax, cell.ymax}, {cell.xmin, cell.ymax}});
  std::shared_ptr<Impl> impl = build(parts, false, {});
  impl->periodicity = axes;
  impl->cell = cell;
  return Domain(std::move(impl));
}

Periodicity Domain::periodicity() const noexcept {
  return impl_->periodicity;
}

const std::vector<Polygon>& Domain::polygons() const noexcept {
  return impl_->polygons;
}
std::size_t Domain::num_polygons() const noexcept {
  return impl_->polygons.size();
}
std::size_t Domain::num_holes() const noexcept {
  return impl_->holes;
}
std::size_t Domain::num_vertices() const noexcept {
  return impl_->rings.v.size();
}
double Domain::area() const noexcept {
  return impl_->area;
}
double Domain::perimeter() const noexcept {
  return impl_->perimeter;
}
Box Domain::bbox() const noexcept {
  return impl_->rings.bbox;
}
double Domain::max_abs_coordinate() const noexcept {
  return impl_->max_abs;
}

Box Domain::bbox(std::size_t polygon) const {
  if (polygon >= impl_->polygon_boxes.size()) {
    throw std::out_of_range("frontpack::Domain::bbox: polygon index " + std::to_string(polygon) + " out of range");
  }
  return impl_->polygon_boxes[polygon];
}

Location Domain::locate(Point p) const noexcept {
  if (impl_->periodicity != Periodicity::none) {
    return detail::locate_in_cell(impl_->cell, impl_->periodicity, p);
  }
  return impl_->grid.locate(p);
}

bool Domain::contains(const Disk& disk) const noexcept {
  if (impl_->periodicity != Periodicity::none) {
    return detail::cell_contains(impl_->cell, impl_->periodicity, disk);
  }
  return impl_->grid.contains(disk);
}

void Domain::contains(std::span<const Disk> disks, std::span<std::uint8_t> out) const {
  if (disks.size() != out.size()) {
    throw std::invalid_argument("frontpack::Domain::contains: " + std::to_string(disks.size()) + " disks but " +
                                std::to_string(out.size()) + " results");
  }
  if (impl_->periodicity != Periodicity::none) {
    for (std::size_t i = 0; i < disks.size(); ++i) {
      out[i] = detail::cell_contains(impl_->cell, impl_->periodicity, disks[i]) ? 1 : 0;
    }
    return;
  }
  for (std::size_t i = 0; i < disks.size(); ++i) {
    out[i] = impl_->grid.contains(disks[i]) ? 1 : 0;
  }
}

std::string Domain::to_wkt() const {
  const auto& polys = impl_->polygons;
  std::string out = polys.size() == 1 ? "POLYGON " : "MULTIPOLYGON (";
  for (std::size_t p = 0; p < polys.size(); ++p) {
    if (p > 0) {
      out += ", ";
    }
    out += '(';
    append_ring(out, polys[p].outer);
    for (const Ring& hole : polys[p].holes) {
      out += ", ";
      append_ring(out, hole);
    }
    out += ')';
  }
  if (polys.size() != 1) {
    out += ')';
  }
  return out;
}

const char* to_string(Periodicity periodicity) noexcept {
  switch (periodicity) {
    case Periodicity::none: return "none";
    case Periodicity::x: return "x";
    case Periodicity::xy: return "xy";
  }
  return "unknown";
}

const char* to_string(Location location) noexcept {
  switch (location) {
    case Location::outside: return "outside";
    case Location::boundary: return "boundary";
    case Location::inside: return "inside";
  }
  return "unknown";
}

}  // namespace frontpack
