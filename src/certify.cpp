// Certification: exact containment (Domain::contains, through its edge grid) and the global
// overlap pass (CGAL::box_self_intersection_d + an exact pair predicate).
#include <CGAL/Bbox_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "certify.hpp"
#include "exact.hpp"
#include "frontpack/fill.hpp"

namespace frontpack {

namespace detail {

void overlapping_pairs(std::span<const Disk> disks, std::vector<std::pair<std::size_t, std::size_t>>& out,
                       std::size_t& candidates) {
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 2, const Disk*,
                                                           CGAL::Box_intersection_d::ID_FROM_HANDLE>;
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<Box> boxes;
  boxes.reserve(disks.size());
  for (const Disk& d : disks) {
    const double x = d.centre.x;
    const double y = d.centre.y;
    const double r = d.radius;
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(r) || !(r >= 0)) {
      continue;
    }
    // Rounded outwards: the exact box [x - r, x + r] x [y - r, y + r] lies inside.
    boxes.emplace_back(CGAL::Bbox_2(std::nextafter(x - r, -inf), std::nextafter(y - r, -inf),
                                    std::nextafter(x + r, inf), std::nextafter(y + r, inf)),
                       &d);
  }
  const Disk* base = disks.data();
  out.clear();
  candidates = 0;
  // The cutoff of 1000 measured fastest for ~1M disks (docs/design.md).
  CGAL::box_self_intersection_d(
      boxes.begin(), boxes.end(),
      [&](const Box& a, const Box& b) {
        ++candidates;
        const Disk& p = *a.handle();
        const Disk& q = *b.handle();
        if (compare_centre_distance(p.centre, q.centre, p.radius, q.radius) == CGAL::SMALLER) {
          const auto i = static_cast<std::size_t>(a.handle() - base);
          const auto j = static_cast<std::size_t>(b.handle() - base);
          out.emplace_back(std::min(i, j), std::max(i, j));
        }
      },
      std::ptrdiff_t{1000});
  std::sort(out.begin(), out.end());
}

}  // namespace detail

CertifyReport certify(const Domain& domain, std::span<const Disk> disks) {
  CertifyReport report;
  std::vector<std::uint8_t> inside(disks.size());
  domain.contains(disks, inside);
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (inside[i] == 0) {
      report.outside.push_back(i);
    }
  }
  detail::overlapping_pairs(disks, report.overlapping, report.certificate.candidate_pairs);
  report.certificate.generated = disks.size();
  report.certificate.culled = report.outside.size();
  report.certificate.exact = true;
  return report;
}

}  // namespace frontpack
