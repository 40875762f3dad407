#include "certify/cull.hpp"

#include <algorithm>

#include "common/stop.hpp"

namespace frontpack::detail {

void contains(const Domain& domain, std::span<const Disk> disks, std::span<std::uint8_t> inside,
              const std::stop_token& stop) {
  constexpr std::size_t kBlock = std::size_t{1} << 16;
  for (std::size_t begin = 0; begin < disks.size(); begin += kBlock) {
    throw_if_stopped(stop);
    const std::size_t n = std::min(kBlock, disks.size() - begin);
    domain.contains(disks.subspan(begin, n), inside.subspan(begin, n));
  }
}

void contains_in_own_polygon(const Domain& domain, std::span<const Disk> disks, std::span<const std::size_t> part_end,
                             std::span<std::uint8_t> inside, const std::stop_token& stop) {
  if (domain.num_polygons() == 1 || part_end.empty()) {
    contains(domain, disks, inside, stop);
    return;
  }
  std::size_t begin = 0;
  for (std::size_t p = 0; p < part_end.size(); ++p) {
    const std::size_t n = part_end[p] - begin;
    if (n > 0) {
      const Domain part = Domain::from_polygons({domain.polygons()[p]});
      contains(part, disks.subspan(begin, n), inside.subspan(begin, n), stop);
    }
    begin = part_end[p];
  }
}

void keep_where(std::vector<Disk>& disks, const std::vector<std::uint8_t>& flag, std::uint8_t keep) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    if (flag[i] == keep) {
      disks[kept++] = disks[i];
    }
  }
  disks.resize(kept);
}

}  // namespace frontpack::detail
