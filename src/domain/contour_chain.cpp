#include "domain/contour_chain.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "common/format.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

struct End {
  Point p;
  std::size_t piece = 0;
  bool at_start = false;
};

// The ends sorted by x, searched by an x window and then by distance.
class EndIndex {
 public:
  EndIndex(const std::vector<Piece>& pieces, double tolerance) : tol_(tolerance) {
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      ends_.push_back({pieces[i].edges.front().from, i, true});
      ends_.push_back({pieces[i].end, i, false});
    }
    std::sort(ends_.begin(), ends_.end(), [](const End& a, const End& b) {
      return a.p.x < b.p.x || (a.p.x == b.p.x && (a.p.y < b.p.y || (a.p.y == b.p.y && a.piece < b.piece)));
    });
  }

  // Every end within the tolerance of p, except end (piece, at_start) itself, in a fixed order.
  [[nodiscard]] std::vector<End> near(Point p, std::size_t piece, bool at_start) const {
    std::vector<End> out;
    auto it =
        std::lower_bound(ends_.begin(), ends_.end(), p.x - tol_, [](const End& e, double x) { return e.p.x < x; });
    for (; it != ends_.end() && it->p.x <= p.x + tol_; ++it) {
      const double dx = it->p.x - p.x;
      const double dy = it->p.y - p.y;
      if (dx * dx + dy * dy <= tol_ * tol_ && !(it->piece == piece && it->at_start == at_start)) {
        out.push_back(*it);
      }
    }
    return out;
  }

 private:
  std::vector<End> ends_;
  double tol_;
};

Piece reversed(Piece p) {
  Piece r;
  r.name = p.name;
  std::vector<Point> pts;
  for (const ContourEdge& e : p.edges) {
    pts.push_back(e.from);
  }
  pts.push_back(p.end);
  for (std::size_t k = p.edges.size(); k-- > 0;) {
    ContourEdge e = p.edges[k];
    e.from = pts[k + 1];
    if (e.curved) {
      e.arc.start += e.arc.sweep;
      e.arc.sweep = -e.arc.sweep;
    }
    r.edges.push_back(e);
  }
  r.end = pts.front();
  return r;
}

}  // namespace

std::vector<Contour> chain_pieces(std::vector<Piece> pieces, double tolerance, const std::string& source) {
  const EndIndex index(pieces, tolerance);
  std::vector<char> used(pieces.size(), 0);
  std::vector<Contour> contours;
  for (std::size_t first = 0; first < pieces.size(); ++first) {
    if (used[first] != 0) {
      continue;
    }
    used[first] = 1;
    Contour c;
    const auto append = [&c](const Piece& p) {
      const auto name = static_cast<std::uint32_t>(c.names.size());
      c.names.push_back(p.name);
      for (ContourEdge e : p.edges) {
        e.name = name;
        c.edges.push_back(e);
      }
    };
    Piece current = pieces[first];
    std::size_t current_index = first;
    bool current_reversed = false;
    append(current);
    for (std::size_t guard = 0; guard <= pieces.size(); ++guard) {
      // The far end of the current piece as it lies in the chain.
      const std::vector<End> next = index.near(current.end, current_index, current_reversed);
      if (next.empty()) {
        throw DomainFileError(DomainFileError::Kind::open_contour,
                              "open contour: its end " + format_point(current.end) +
                                  " meets no other entity's end (closed polylines need the closed flag)",
                              source, current.name);
      }
      if (next.size() > 1) {
        throw DomainFileError(DomainFileError::Kind::branching_contour,
                              "the end " + format_point(current.end) + " meets " + std::to_string(next.size()) +
                                  " other ends; a boundary needs exactly one (duplicated or overlapping entities?)",
                              source, pieces[next[1].piece].name);
      }
      const End& e = next.front();
      const bool closes = e.piece == first && e.at_start;
      // The joint: a straight edge's written endpoint rather than an arc's computed one.
      const bool last_straight = !c.edges.back().curved;
      if (closes) {
        if (last_straight && c.edges.front().curved) {
          c.edges.front().from = current.end;
        }
        break;
      }
      if (used[e.piece] != 0) {
        throw DomainFileError(DomainFileError::Kind::branching_contour,
                              "the end " + format_point(current.end) + " meets an entity already in another contour",
                              source, pieces[e.piece].name);
      }
      used[e.piece] = 1;
      const Point joint = current.end;
      current = e.at_start ? pieces[e.piece] : reversed(pieces[e.piece]);
      current_index = e.piece;
      current_reversed = !e.at_start;
      if (last_straight && current.edges.front().curved) {
        current.edges.front().from = joint;
      }
      append(current);
    }
    contours.push_back(std::move(c));
  }
  return contours;
}

}  // namespace frontpack::detail
