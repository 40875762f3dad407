// The flat, validated form of a domain's rings, shared by validation and the spatial index.
// Built and measured in ring_set.cpp; validated in domain/validate.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "domain/edge_grid.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

struct RingInfo {
  std::uint32_t part = 0;
  std::uint32_t ring = 0;   ///< 0 = outer ring, k = hole k (input numbering)
  std::uint32_t first = 0;  ///< first vertex in RingSet::v
  std::uint32_t count = 0;
};

/// All rings, open, without repeated consecutive vertices, in input order and orientation.
/// Edge k runs from v[k] to v[next[k]].
struct RingSet {
  std::vector<Point> v;
  std::vector<std::uint32_t> next;
  std::vector<std::uint32_t> prev;
  std::vector<std::uint32_t> ring_of;
  std::vector<std::uint32_t> source;  ///< index of the vertex in its ring as written
  std::vector<RingInfo> rings;
  std::vector<std::uint32_t> part_first_ring;  ///< rings of part p: [part_first_ring[p], part_first_ring[p+1])
  Box bbox;
};

/// Input rings: parts -> rings -> points (ring 0 outer).
using RawParts = std::vector<std::vector<std::vector<Point>>>;

/// Describes where a vertex was written (" at line 3, column 7"), or "" when unknown.
using SourceLocator = std::function<std::string(std::size_t part, std::size_t ring, std::size_t vertex)>;

/// Checks coordinates, closure (when `require_closed`), and vertex counts; drops the closing
/// vertex and repeated consecutive vertices. Throws InvalidDomainError.
[[nodiscard]] RingSet make_ring_set(const RawParts& parts, bool require_closed, const SourceLocator& where);

/// Full OGC validity check of the rings; on success builds `grid` over them (classified).
/// Throws InvalidDomainError naming the first problem found.
void validate(const RingSet& rings, EdgeGrid& grid, const SourceLocator& where);

/// Exact signed area of ring r (positive when anticlockwise), rounded to nearest; and the exact
/// area of the whole domain (outer rings minus holes) rounded to nearest.
[[nodiscard]] int ring_orientation(const RingSet& rings, std::size_t r);
[[nodiscard]] double exact_domain_area(const RingSet& rings);

/// "polygon 0, outer ring" / "polygon 2, hole 1": a ring named as messages name it.
[[nodiscard]] std::string ring_name(std::size_t part, std::size_t ring);
/// "vertex 3 (x y)" followed by where it was written, when known.
[[nodiscard]] std::string vertex_text(std::size_t part, std::size_t ring, std::size_t vertex, Point p,
                                      const SourceLocator& where);

}  // namespace frontpack::detail
