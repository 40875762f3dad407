// The status of a plane sweep over segments (domain/ring_tree.cpp, domain/edge_sweep.cpp): points are swept in
// lexicographic order (x, then y), as by a vertical line tilted by an infinitesimal angle, so that
// no segment is parallel to it and every event is an endpoint. The status orders the segments
// the line crosses from bottom to top, decided exactly.
#pragma once

#include <cstdint>

#include "exact/predicates.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

inline bool lex_less(Point a, Point b) noexcept {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// A segment with its endpoints in sweep order.
struct SweepEdge {
  Point lo;  ///< lexicographically smaller endpoint
  Point hi;
  std::uint32_t id;
};

inline SweepEdge sweep_edge(Point a, Point b, std::uint32_t id) noexcept {
  return lex_less(a, b) ? SweepEdge{a, b, id} : SweepEdge{b, a, id};
}

/// Whether a lies below b on the sweep line, for two segments that it both crosses (just after
/// the current event, where the later-starting one starts). Exact; a strict order for segments
/// that neither cross nor overlap. Collinear overlapping segments compare equivalent.
struct Below {
  bool operator()(const SweepEdge& a, const SweepEdge& b) const {
    if (a.id == b.id) {
      return false;
    }
    if (a.lo == b.lo) {
      return orientation(a.lo, a.hi, b.hi) > 0;
    }
    if (lex_less(a.lo, b.lo)) {
      // b starts on the sweep line, over a's span; if it starts on a, its other end decides.
      int o = orientation(a.lo, a.hi, b.lo);
      if (o == 0) {
        o = orientation(a.lo, a.hi, b.hi);
      }
      return o > 0;
    }
    int o = orientation(b.lo, b.hi, a.lo);
    if (o == 0) {
      o = orientation(b.lo, b.hi, a.hi);
    }
    return o < 0;
  }
};

}  // namespace frontpack::detail
