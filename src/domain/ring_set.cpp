// Building the flat ring set from input rings, and exact ring areas (domain/ring_set.hpp).
#include "domain/ring_set.hpp"

#include <CGAL/Mpzf.h>

#include <cmath>
#include <string>

#include "common/format.hpp"

namespace frontpack::detail {

namespace {

using Kind = InvalidDomainError::Kind;
using Site = InvalidDomainError::Site;

}  // namespace

std::string ring_name(std::size_t part, std::size_t ring) {
  return "polygon " + std::to_string(part) + (ring == 0 ? ", outer ring" : ", hole " + std::to_string(ring));
}

std::string vertex_text(std::size_t part, std::size_t ring, std::size_t vertex, Point p, const SourceLocator& where) {
  return "vertex " + std::to_string(vertex) + " " + format_point(p) + (where ? where(part, ring, vertex) : "");
}

RingSet make_ring_set(const RawParts& parts, bool require_closed, const SourceLocator& where) {
  RingSet rs;
  if (parts.empty()) {
    throw InvalidDomainError(Kind::empty, "the domain has no polygon", Site{});
  }
  for (std::size_t p = 0; p < parts.size(); ++p) {
    rs.part_first_ring.push_back(static_cast<std::uint32_t>(rs.rings.size()));
    if (parts[p].empty()) {
      throw InvalidDomainError(Kind::empty, "polygon " + std::to_string(p) + " has no ring", Site{p, 0, {}});
    }
    for (std::size_t r = 0; r < parts[p].size(); ++r) {
      const std::vector<Point>& pts = parts[p][r];
      for (std::size_t k = 0; k < pts.size(); ++k) {
        const Point q = pts[k];
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) {
          throw InvalidDomainError(
              Kind::non_finite_coordinate,
              ring_name(p, r) + ": " + vertex_text(p, r, k, q, where) + " has a non-finite coordinate", Site{p, r, k},
              {}, q);
        }
        if (std::abs(q.x) > max_coordinate || std::abs(q.y) > max_coordinate) {
          throw InvalidDomainError(Kind::coordinate_out_of_range,
                                   ring_name(p, r) + ": " + vertex_text(p, r, k, q, where) +
                                       " is out of range: |coordinate| must be at most " +
                                       format_double(max_coordinate),
                                   Site{p, r, k}, {}, q);
        }
      }
      if (pts.empty()) {
        throw InvalidDomainError(Kind::too_few_vertices, ring_name(p, r) + ": the ring has no vertex", Site{p, r, {}});
      }
      std::size_t n = pts.size();
      if (require_closed && pts.front() != pts.back()) {
        throw InvalidDomainError(Kind::unclosed_ring,
                                 ring_name(p, r) + ": the ring is not closed: its last point, " +
                                     vertex_text(p, r, n - 1, pts.back(), where) + ", differs from its first " +
                                     format_point(pts.front()),
                                 Site{p, r, n - 1}, {}, pts.back());
      }
      if (n >= 2 && pts.front() == pts.back()) {
        --n;  // drop the closing vertex
      }
      RingInfo info{static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(r),
                    static_cast<std::uint32_t>(rs.v.size()), 0};
      for (std::size_t k = 0; k < n; ++k) {
        if (info.count > 0 && rs.v.back() == pts[k]) {
          continue;  // repeated consecutive vertex
        }
        rs.v.push_back(pts[k]);
        rs.source.push_back(static_cast<std::uint32_t>(k));
        ++info.count;
      }
      while (info.count > 1 && rs.v.back() == rs.v[info.first]) {
        rs.v.pop_back();  // repeats of the first vertex at the end
        rs.source.pop_back();
        --info.count;
      }
      if (info.count < 3) {
        throw InvalidDomainError(Kind::too_few_vertices,
                                 ring_name(p, r) + ": the ring has " + std::to_string(info.count) + " distinct " +
                                     (info.count == 1 ? "vertex" : "vertices") + "; a ring needs at least 3" +
                                     (where ? where(p, r, 0) : std::string()),
                                 Site{p, r, {}}, {}, pts.front());
      }
      const auto ring_index = static_cast<std::uint32_t>(rs.rings.size());
      for (std::uint32_t k = 0; k < info.count; ++k) {
        const std::uint32_t i = info.first + k;
        rs.next.push_back(k + 1 == info.count ? info.first : i + 1);
        rs.prev.push_back(k == 0 ? info.first + info.count - 1 : i - 1);
        rs.ring_of.push_back(ring_index);
        rs.bbox.extend(rs.v[i]);
      }
      rs.rings.push_back(info);
    }
  }
  rs.part_first_ring.push_back(static_cast<std::uint32_t>(rs.rings.size()));
  return rs;
}

namespace {

// Twice the signed area of ring r, exactly.
CGAL::Mpzf twice_area(const RingSet& rs, std::size_t r) {
  const RingInfo& info = rs.rings[r];
  CGAL::Mpzf sum(0);
  for (std::uint32_t k = info.first; k < info.first + info.count; ++k) {
    const Point a = rs.v[k];
    const Point b = rs.v[rs.next[k]];
    sum += CGAL::Mpzf(a.x) * CGAL::Mpzf(b.y) - CGAL::Mpzf(a.y) * CGAL::Mpzf(b.x);
  }
  return sum;
}

// The double nearest to x (ties to even).
double nearest_double(const CGAL::Mpzf& x) {
  const auto [lo, hi] = x.to_interval();
  if (lo == hi) {
    return lo;
  }
  // lo and hi are adjacent doubles around x: compare 2x with lo + hi exactly.
  const CGAL::Comparison_result c = CGAL::compare(x * CGAL::Mpzf(2), CGAL::Mpzf(lo) + CGAL::Mpzf(hi));
  if (c == CGAL::SMALLER) {
    return lo;
  }
  if (c == CGAL::LARGER) {
    return hi;
  }
  int exp = 0;
  const double mant = std::frexp(lo, &exp);
  const auto bits = static_cast<long long>(std::ldexp(mant, 53));
  return (bits % 2 == 0) ? lo : hi;
}

}  // namespace

int ring_orientation(const RingSet& rings, std::size_t r) {
  return static_cast<int>(twice_area(rings, r).sign());
}

double exact_domain_area(const RingSet& rings) {
  CGAL::Mpzf total(0);
  for (std::size_t r = 0; r < rings.rings.size(); ++r) {
    const CGAL::Mpzf a = twice_area(rings, r);
    const bool outer = rings.rings[r].ring == 0;
    // |area| of the outer ring minus |area| of each hole.
    if ((a.sign() > 0) == outer) {
      total += a;
    } else {
      total -= a;
    }
  }
  // total is twice the area; halving a double is exact (barring underflow).
  return nearest_double(total) / 2.0;
}

}  // namespace frontpack::detail
