// Open pieces (DXF LINE, ARC, open polylines) joined end to end into closed contours.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "domain/contour.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack::detail {

/// An open chain of edges from edges.front().from to `end`, made by one entity.
struct Piece {
  std::vector<ContourEdge> edges;
  Point end{};
  std::string name;
};

/// Joins the pieces into closed contours: two ends join when they are at most `tolerance` apart
/// (Euclidean). At a joint the written endpoint of a straight edge is kept over an arc's computed
/// one. Throws DomainFileError naming `source` and the entity: open_contour when an end meets no
/// other end, branching_contour when it meets more than one.
[[nodiscard]] std::vector<Contour> chain_pieces(std::vector<Piece> pieces, double tolerance, const std::string& source);

}  // namespace frontpack::detail
