#include "jam/jam.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "domain/edge_distance.hpp"
#include "jam/insertion.hpp"
#include "jam/relaxation.hpp"

namespace frontpack::detail {

namespace {

// Steps a round may take. A round the packing can take relaxes in 1,000-9,000 steps at 10,000-
// 40,000 disks (docs/jam.md); one it cannot take is given up when it stalls (relaxation.cpp), at
// about 2,000 steps. This bounds the rest.
constexpr std::size_t kSteps = 20000;
// The first round inserts 1/64 of the disks (an unjammed packing takes 3-4% more); the last tried
// inserts 1/4096.
constexpr std::size_t kFirstShare = 64;
constexpr std::size_t kLastShare = 4096;

// Whether every disk lies in the domain, decided exactly. A disk pressed hard enough against a
// wall by the disks inserted behind it can cross it (each step moves it at most 0.1 rmin, but the
// wall holds it with a force of at most its radius), and once its centre is across, the wall pushes
// it on outwards, possibly beyond the reach of any later check of the walls near it; so every
// round kept is checked whole (a few exact tests per disk, against thousands of relaxation steps).
bool all_inside(const Domain& domain, const std::vector<Disk>& disks, std::vector<std::uint8_t>& inside) {
  inside.resize(disks.size());
  domain.contains(disks, inside);
  return std::all_of(inside.begin(), inside.end(), [](std::uint8_t b) { return b != 0; });
}

}  // namespace

JamReport jam(const Domain& domain, const RadiusDistribution& radii, double clearance, std::size_t max_disks, Rng& rng,
              std::vector<Disk>& disks, const std::function<bool(std::size_t, double)>& tick,
              const std::stop_token& stop) {
  const auto t0 = std::chrono::steady_clock::now();
  JamReport report;
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
  // The fraction of the rounds done, as the halvings of k from the first to the last.
  const double halvings = std::log2(static_cast<double>(k) / static_cast<double>(last)) + 1;
  // (k reaches 0 after the last round: 1.)
  const auto done = [&] {
    const double left = k == 0 ? 0 : std::log2(static_cast<double>(k) / static_cast<double>(last)) + 1;
    return std::clamp(1 - left / halvings, 0.0, 1.0);
  };
  bool going = true;
  const std::function<bool()> keep_going = [&] { return !tick || (going = going && tick(disks.size(), done())); };
  std::vector<Disk> trial;
  std::vector<std::uint8_t> inside;
  Insertion insertion(domain, walls, frame.periodicity, box, frame.rmin, frame.rmax, disks, rng);
  while (k >= last && !disks.empty() && going && disks.size() < max_disks) {
    trial = disks;
    insertion.insert(trial, std::min(k, max_disks - disks.size()), radii, rng);
    ++report.rounds;
    const bool relaxed = relaxation.run(trial, kSteps, keep_going, stop);
    report.steps += relaxation.iterations();
    // A round that inserted nothing (a domain too thin for a candidate point) fails too, so that
    // k shrinks and the stage ends.
    if (relaxed && going && trial.size() > disks.size() && all_inside(domain, trial, inside)) {
      report.inserted += trial.size() - disks.size();
      disks.swap(trial);
    } else {
      k /= 2;
    }
    going = going && keep_going();
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  report.cancelled = !going;
  return report;
}

}  // namespace frontpack::detail
