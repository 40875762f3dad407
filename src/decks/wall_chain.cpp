// The verification of a ring's wall chain (wall_chain.hpp): every statement a deck makes about its
// walls, checked on the disks it writes.
#include "decks/wall_chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "common/format.hpp"
#include "frontpack/errors.hpp"

namespace frontpack::detail {

namespace {

// Distance from p to the segment [a, b].
double segment_distance(Point p, Point a, Point b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

}  // namespace

double wall_radius_floor(const Box& bbox) {
  const double m = std::max({std::abs(bbox.xmin), std::abs(bbox.xmax), std::abs(bbox.ymin), std::abs(bbox.ymax),
                             std::numeric_limits<double>::min()});
  const double ulp = std::nextafter(m, std::numeric_limits<double>::infinity()) - m;
  return 8 * ulp / 1e-6;
}

void verify_wall_chain(const Domain& outside, const Ring& ring, std::span<const ChainDisk> chain, double wall_radius,
                       double rmin, const std::string& where) {
  const std::string head = "walls: the wall disks of radius " + format_double(wall_radius) + " along " + where;
  const std::string advice = "; use a smaller wall radius";
  if (chain.size() < 3) {
    throw OptionError("walls: no closed chain of wall disks of radius " + format_double(wall_radius) +
                      " fits outside " + where + advice);
  }
  std::vector<Disk> disks;
  disks.reserve(chain.size());
  for (const ChainDisk& c : chain) {
    disks.push_back(c.disk);
  }
  std::vector<std::uint8_t> ok(disks.size());
  outside.contains(disks, ok);
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (ok[i] == 0) {
      throw OptionError(head + ": the wall disk at " + format_point(disks[i].centre) + " is not outside the domain" +
                        advice);
    }
  }
  // The margin covers the rounding of hypot and of the segment distance (a few ulps).
  const double reach = 2 * (wall_radius + rmin) * (1 - 1e-12);
  const std::size_t n = ring.size();
  // Whether the wall disk centred at c closes the corner at vertex k: it leaves a gap narrower
  // than 2 rmin to the lines of both edges that meet there (the disk placed where the two offset
  // lines meet, or the last one before it, which kept it out as a near-duplicate).
  const double touch = (wall_radius + 2 * rmin) * (1 - 1e-12);
  const auto closes_corner = [&](Point c, std::size_t k) {
    const Point v = ring[k];
    for (const Point w : {ring[(k + n - 1) % n], ring[(k + 1) % n]}) {
      const double len = std::hypot(w.x - v.x, w.y - v.y);
      if (!(std::abs((w.x - v.x) * (c.y - v.y) - (w.y - v.y) * (c.x - v.x)) < touch * len)) {
        return false;
      }
    }
    return true;
  };
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const ChainDisk& a = chain[i];
    const ChainDisk& b = chain[(i + 1) % chain.size()];
    const Point pa = a.disk.centre;
    const Point pb = b.disk.centre;
    if (!(std::hypot(pb.x - pa.x, pb.y - pa.y) < reach)) {
      throw OptionError(head + " leave a gap between " + format_point(pa) + " and " + format_point(pb) +
                        " that a disk of radius " + format_double(rmin) +
                        " could pass (no wall disk fits there outside the domain)" + advice);
    }
    // The ring vertices passed over between a's edge and b's: vertices a.edge + 1 .. b.edge, and
    // round the end of the ring from the last disk to the first. Edges never go back.
    const bool last = i + 1 == chain.size();
    if (!last && b.edge < a.edge) {
      throw OptionError(head + " do not follow the ring: the wall disk at " + format_point(pb) +
                        " comes back to an earlier edge" + advice);
    }
    const std::size_t to = last ? b.edge + n : b.edge;
    for (std::size_t k = a.edge + 1; k <= to; ++k) {
      const Point v = ring[k % n];
      if (!(segment_distance(v, pa, pb) < reach) && !closes_corner(pa, k % n) && !closes_corner(pb, k % n)) {
        throw OptionError(
            "walls: the chain of wall disks of radius " + format_double(wall_radius) + " does not cover " + where +
            ": its vertex " + format_point(v) + " is farther than 2 (wall radius + " + format_double(rmin) +
            ") from the chain, between the wall disks at " + format_point(pa) + " and " + format_point(pb) + advice);
      }
    }
  }
}

}  // namespace frontpack::detail
