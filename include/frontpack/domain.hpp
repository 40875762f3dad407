// frontpack: polygonal domains.
//
// A Domain is one or more polygons with holes (a MULTIPOLYGON), validated by the OGC Simple
// Features rules and normalised: outer rings anticlockwise, holes clockwise, no repeated
// consecutive vertices, rings stored open (the closing vertex is not repeated).
//
// Exactness: the domain stores the input coordinates as doubles and every query is decided
// exactly on them (CGAL filtered predicates: interval arithmetic first, exact multiprecision
// arithmetic when the interval answer is uncertain). No tolerance is applied anywhere.
//
// A Domain is immutable and cheap to copy (copies share the validated geometry and its index);
// it is safe to query from several threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frontpack/errors.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack {

/// Largest accepted |coordinate|. Beyond it the floating-point filters of the exact predicates
/// would overflow on every call; no physical domain comes close.
inline constexpr double max_coordinate = 1e100;

/// A closed ring, stored open: vertex i is joined to vertex (i + 1) % size().
using Ring = std::vector<Point>;

/// One polygon with holes.
struct Polygon {
  Ring outer;               ///< anticlockwise after normalisation
  std::vector<Ring> holes;  ///< clockwise after normalisation
};

/// Where a point lies relative to a domain. `boundary` means exactly on an edge or vertex.
enum class Location : std::uint8_t { outside = 0, boundary = 1, inside = 2 };

[[nodiscard]] const char* to_string(Location location) noexcept;

/// Which directions of a domain wrap around (Domain::periodic()).
enum class Periodicity : std::uint8_t {
  none,  ///< a polygonal domain
  x,     ///< a cell periodic in x, with walls at its bottom and top (a shear cell)
  xy,    ///< a cell periodic in x and y (a flat torus)
};

[[nodiscard]] const char* to_string(Periodicity periodicity) noexcept;

class Domain {
 public:
  /// Parses a WKT POLYGON or MULTIPOLYGON (keywords in any case, any whitespace, scientific
  /// notation). Throws WktError for text that is not such a geometry and InvalidDomainError for a
  /// geometry that is not valid. Numbers are read with correct rounding; one out of the range of
  /// doubles, whether it overflows ("1e400") or underflows to 0 ("1e-400"), is a WktError
  /// (bad_number), never rounded quietly; subnormal values are kept (README, "Numbers").
  [[nodiscard]] static Domain from_wkt(std::string_view wkt);

  /// Reads a WKT file. Throws IoError if it cannot be read, then as from_wkt; the messages name
  /// the file.
  [[nodiscard]] static Domain from_wkt_file(const std::filesystem::path& path);

  /// Builds a domain from rings. Each ring may be given open or closed (a last vertex equal to
  /// the first is dropped), in either orientation. Throws InvalidDomainError.
  [[nodiscard]] static Domain from_polygons(std::vector<Polygon> polygons);
  [[nodiscard]] static Domain from_rings(Ring outer, std::vector<Ring> holes = {});

  /// A periodic cell: the box [xmin, xmax) x [ymin, ymax), whose periods are xmax - xmin and
  /// ymax - ymin, taken exactly (not rounded). A disk belongs to the cell when its centre does
  /// (half-open on a periodic axis: xmin <= x < xmax); it may reach across a periodic side, where
  /// it meets the images of the other disks, translated by whole periods. With Periodicity::x
  /// the bottom and top are walls: a disk must lie between them (closed). polygons(), area(),
  /// bbox() and to_wkt() describe the cell's rectangle (WKT carries no periodicity). Throws
  /// InvalidDomainError for a box that is empty, not finite, beyond max_coordinate, or whose
  /// period rounds to 0 or overflows; OptionError for Periodicity::none.
  [[nodiscard]] static Domain periodic(const Box& cell, Periodicity axes = Periodicity::xy);

  /// Periodicity::none for a polygonal domain.
  [[nodiscard]] Periodicity periodicity() const noexcept;

  /// The normalised polygons, in input order.
  [[nodiscard]] const std::vector<Polygon>& polygons() const noexcept;
  [[nodiscard]] std::size_t num_polygons() const noexcept;
  [[nodiscard]] std::size_t num_holes() const noexcept;
  [[nodiscard]] std::size_t num_vertices() const noexcept;

  /// Area: the exact area of the domain rounded to the nearest double.
  [[nodiscard]] double area() const noexcept;
  /// Perimeter of all rings (floating point, for reporting).
  [[nodiscard]] double perimeter() const noexcept;
  /// Bounding box of the domain, and of one polygon.
  [[nodiscard]] Box bbox() const noexcept;
  [[nodiscard]] Box bbox(std::size_t polygon) const;
  /// Largest |coordinate| of any vertex: the scale of the floating-point error of constructions.
  [[nodiscard]] double max_abs_coordinate() const noexcept;

  /// Exact point location. A periodic cell: `inside` in the half-open cell (Periodicity::x:
  /// strictly between the walls), `boundary` on a wall (Periodicity::x: y = ymin or ymax with
  /// xmin <= x < xmax), `outside` otherwise; a periodic side is no boundary.
  [[nodiscard]] Location locate(Point p) const noexcept;

  /// Exact: whether the closed disk lies in the closed domain (touching the boundary counts as
  /// inside). A disk with a negative or NaN radius is never inside. A periodic cell: whether the
  /// centre lies in the half-open cell and, with Periodicity::x, the closed disk between the walls
  /// (decided exactly; an infinite radius is never inside).
  [[nodiscard]] bool contains(const Disk& disk) const noexcept;

  /// Batch form of contains(): out[i] = contains(disks[i]). Uses the domain's spatial index, so
  /// the cost is about constant per disk, independent of the number of edges for disks away from
  /// the boundary. Precondition: out.size() == disks.size() (else std::invalid_argument).
  void contains(std::span<const Disk> disks, std::span<std::uint8_t> out) const;

  /// The domain as WKT (POLYGON for one polygon, else MULTIPOLYGON), with shortest round-trip
  /// number formatting: from_wkt(to_wkt()) gives an identical domain.
  [[nodiscard]] std::string to_wkt() const;

  struct Impl;

 private:
  explicit Domain(std::shared_ptr<const Impl> impl) noexcept;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace frontpack
