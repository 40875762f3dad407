#include "jam/jam.hpp"

#include <algorithm>
#include <chrono>

#include "domain/edge_distance.hpp"
#include "jam/relaxation.hpp"

namespace frontpack::detail {

namespace {

// Steps a round may take. A round the packing can take relaxes in 1,000-5,000 steps at 10,000-
// 40,000 disks (docs/jam.md); one it cannot take is given up when it stalls (relaxation.cpp), at
// about 2,000 steps. This bounds the rest.
constexpr std::size_t kSteps = 20000;
// The first round inserts 1/64 of the disks (an unjammed packing takes 3-4% more); the last tried
// inserts 1/4096.
constexpr std::size_t kFirstShare = 64;
constexpr std::size_t kLastShare = 4096;
// Draws of a point in the domain's box per point inside: a domain that covers less than 1/64 of
// its box (a thin ring) gets fewer disks per round.
constexpr std::size_t kTries = 64;

// A point drawn uniformly in the domain (rejection in its box), or false after kTries misses.
bool draw_point(const Domain& domain, const Box& box, Rng& rng, Point& out) {
  for (std::size_t t = 0; t < kTries; ++t) {
    out = Point{box.xmin + rng.uniform() * (box.xmax - box.xmin), box.ymin + rng.uniform() * (box.ymax - box.ymin)};
    if (domain.locate(out) == Location::inside) {
      return true;
    }
  }
  return false;
}

// Whether every disk that could have reached a wall still has its centre inside the domain: the
// relaxation pushes a disk off a wall from the wall's side it is on, so one pressed through a
// wall would be pushed on outwards. (The others cannot have crossed one: Relaxation::near_wall().)
bool stayed_inside(const Domain& domain, const std::vector<Disk>& disks, const std::vector<std::uint32_t>& near_wall) {
  return std::all_of(near_wall.begin(), near_wall.end(),
                     [&](std::uint32_t i) { return domain.locate(disks[i].centre) == Location::inside; });
}

}  // namespace

void jam(const Domain& domain, const RadiusDistribution& radii, double clearance, Rng& rng, std::vector<Disk>& disks,
         const std::stop_token& stop, FillStats& stats) {
  const auto t0 = std::chrono::steady_clock::now();
  const Box box = domain.bbox();
  const EdgeDistanceIndex walls(domain, 2 * radii.max());
  RelaxationFrame frame;
  frame.walls = &walls;
  frame.periodicity = domain.periodicity();
  frame.cell = box;
  frame.rmin = radii.min();
  frame.rmax = radii.max();
  frame.least_gap = 4 * clearance;
  Relaxation relaxation(frame);

  const std::size_t n = disks.size();
  std::size_t k = std::max<std::size_t>(1, n / kFirstShare);
  const std::size_t last = std::max<std::size_t>(1, n / kLastShare);
  std::vector<Disk> trial;
  while (k >= last && !disks.empty()) {
    trial = disks;
    Point p;
    for (std::size_t q = 0; q < k && draw_point(domain, box, rng, p); ++q) {
      trial.push_back(Disk{p, radii.quantile(rng.uniform())});
    }
    ++stats.jam_rounds;
    const bool relaxed = relaxation.run(trial, kSteps, stop);
    stats.jam_steps += relaxation.iterations();
    if (relaxed && stayed_inside(domain, trial, relaxation.near_wall())) {
      stats.jam_inserted += trial.size() - disks.size();
      disks.swap(trial);
    } else {
      k /= 2;
    }
  }
  stats.seconds_jam = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace frontpack::detail
