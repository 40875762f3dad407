// Validation of polygonal domains by the OGC Simple Features rules, decided exactly.
//
// Why not CGAL::is_valid_polygon_with_holes: its hole test is quadratic in practice (measured
// 18-24 s for 30k edges, 459 s for 100k, see shared/design.md) and it prints. Here every pair of
// edges whose boxes meet is found by CGAL::box_self_intersection_d and classified with exact
// orientation tests; ring nesting is decided by exact ray parity through the edge grid, or where
// that would be quadratic by a plane sweep that finds each ring's innermost enclosing ring
// (domain/ring_tree.cpp, exact orientation tests); and the connectivity of each polygon's interior
// follows from the graph of touching rings. Where the edges' boxes meet in far more pairs than
// there are edges (long edges fanning around a common region, as in a star with thousands of
// spikes) and none of them has shown a problem or a touch, a sweep (domain/edge_sweep.cpp, O(n log n))
// decides whether any pair would. Points where the vertices of many rings meet (hubs) are
// classified by sorting their edges by angle, not pair by pair (find_hubs()).
#include "domain/validator.hpp"

namespace frontpack::detail {

namespace validation {

void Validator::run(EdgeGrid& grid) {
  check_collinear_rings();
  check_edge_pairs();
  check_touch_crossings();
  grid.build(rs_.v, rs_.next, rs_.bbox, std::max<std::size_t>(4 * rs_.v.size(), 4096));
  check_nesting(grid);
  check_connectivity();
  grid.classify_cells();
}

void Validator::check_collinear_rings() const {
  for (std::uint32_t r = 0; r < rs_.rings.size(); ++r) {
    const RingInfo& info = ring(r);
    const Point a = rs_.v[info.first];
    const Point b = rs_.v[info.first + 1];  // differs from a: repeats were removed
    bool flat = true;
    for (std::uint32_t k = 2; k < info.count && flat; ++k) {
      flat = orientation(a, b, rs_.v[info.first + k]) == 0;
    }
    if (flat) {
      throw InvalidDomainError(
          Kind::zero_area,
          name(r) + ": the ring has zero area: all its vertices are collinear, from " + vertex(info.first),
          site(info.first), {}, a);
    }
  }
}

}  // namespace validation

void validate(const RingSet& rings, EdgeGrid& grid, const SourceLocator& where) {
  validation::Validator(rings, where).run(grid);
}

}  // namespace frontpack::detail
