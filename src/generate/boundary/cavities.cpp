// The cavity pass (cavities.hpp). Once per polygon, after the front: out of line.
#include "generate/boundary/cavities.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace frontpack::detail {

std::vector<Gap> cavity_gaps(Obstacles& obstacles, const Elements& elements, const RunFrame& frame, std::size_t placed,
                             const std::stop_token& stop) {
  std::vector<Gap> found;
  const double h = std::sqrt(2.0) * (frame.rmax - frame.rmin);
  if (!(h >= frame.rmax)) {
    return found;  // rmax / rmin below 3.4: more than about one probe per disk
  }
  const auto nx = static_cast<std::size_t>(std::min(frame.width / h + 1, 1e8));
  const auto ny = static_cast<std::size_t>(std::min(frame.height / h + 1, 1e8));
  if (nx * ny > 4 * placed + 1024) {
    return found;
  }
  const double r = frame.rmin;
  for (std::size_t j = 0; j < ny; ++j) {
    if (j % 32 == 0 && stop.stop_requested()) {
      return {};  // fill() throws CancelledError once the front returns
    }
    const double y = (static_cast<double>(j) + 0.5) * h;
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = (static_cast<double>(i) + 0.5) * h;
      if (!(x - r >= 0 && x + r <= frame.width && y - r >= 0 && y + r <= frame.height) ||
          obstacles.covered_in_cell(elements, x, y, r) ||
          obstacles.deepest<true>(elements, obstacles.probe(x, y, r)) != kNoElement || !obstacles.inside(x, y)) {
        continue;
      }
      const std::array<std::int32_t, 2> ab = obstacles.nearest_disks(elements, x, y, 2 * frame.rmax);
      if (ab[1] == kNoElement) {
        continue;
      }
      // (In a periodic cell, either may be an image: its position is the one near (x, y), and
      // the gap names its disk.)
      const BoundaryNode& a = elements.node(ab[0]);
      const BoundaryNode& b = elements.node(ab[1]);
      const bool left = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) > 0;
      const std::int32_t ra = elements.real(ab[0]);
      const std::int32_t rb = elements.real(ab[1]);
      found.push_back(left ? Gap{ra, rb} : Gap{rb, ra});
    }
  }
  return found;
}

}  // namespace frontpack::detail
