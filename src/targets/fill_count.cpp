// The fill to a count (targets.hpp). The closed form: its generators stopped a little after the
// count, and the first `count` certified disks kept; the certifier keeps the generation order, so
// these are the blob the front grew about its start point. The open form: its front climbs as a
// ramp (it advances along the front, not level by level), so the first disks it placed reach
// half again as high as a level fill of the same count; it fills the whole domain instead and
// keeps the `count` disks whose tops (y + r) are lowest: the dense fill's bottom, its top level.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "targets/targets.hpp"

namespace frontpack::detail {

Packing fill_to_count(const Domain& domain, const FillOptions& options, const PlainFill& plain) {
  const std::size_t n = options.count;
  // The plain fill keeps options.count: its estimate is the cap (limits.hpp), not the domain's.
  const FillOptions& o = options;
  TargetReport t;
  t.count_requested = n;
  t.area_filled = domain.area();
  // The paper's forms cull the disks that overhang the polygons' boxes: generate a little more
  // than the count, and more again (from the start: the run is deterministic) if that fell short.
  std::size_t cap = o.method == Method::open ? o.max_disks : std::min(o.max_disks, n + n / 8 + 64);
  Packing p;
  for (;;) {
    p = plain(domain, o, cap);
    ++t.fills;
    if (p.disks.size() >= n || !p.truncated || cap == o.max_disks || p.cancelled) {
      break;
    }
    cap = std::min(o.max_disks, cap > o.max_disks / 2 ? o.max_disks : 2 * cap);
  }
  // The generators stopped at the cap, not at a limit the caller set, unless it is max_disks.
  p.truncated = p.truncated && p.disks.size() < n && cap == o.max_disks;
  if (p.disks.size() > n && o.method == Method::open) {
    std::vector<std::size_t> order(p.disks.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      order[i] = i;
    }
    const auto top = [&p](std::size_t i) { return p.disks[i].centre.y + p.disks[i].radius; };
    std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                     [&top](std::size_t a, std::size_t b) { return top(a) < top(b) || (top(a) == top(b) && a < b); });
    order.resize(n);
    std::sort(order.begin(), order.end());  // the generation order among those kept
    std::vector<Disk> kept(n);
    for (std::size_t k = 0; k < n; ++k) {
      kept[k] = p.disks[order[k]];
    }
    p.disks = std::move(kept);
  }
  if (p.disks.size() > n) {
    p.disks.resize(n);
  }
  t.count_achieved = p.disks.size();
  t.fraction_achieved = disk_area(p.disks) / t.area_filled;
  p.target = t;
  return p;
}

}  // namespace frontpack::detail
