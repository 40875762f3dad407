// The jam stage (FillOptions::jam): after the front and its certification, the packing is made
// denser, toward the jammed packing of the same radii, by inserting disks and relaxing the
// overlaps away (relaxation.hpp), round by round. docs/jam.md.
#pragma once

#include <cstddef>
#include <functional>
#include <stop_token>
#include <vector>

#include "common/rng.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/geometry.hpp"
#include "frontpack/sizes.hpp"

namespace frontpack::detail {

/// What the jam stage did (FillStats' jam_* fields and seconds_jam).
struct JamReport {
  std::size_t rounds = 0;    ///< rounds of insertion and relaxation
  std::size_t inserted = 0;  ///< disks inserted by the rounds kept
  std::size_t steps = 0;     ///< relaxation steps, every round
  double seconds = 0;        ///< wall time of the stage
  bool cancelled = false;    ///< `tick` returned false: the round under way was undone
};

/// Jams `disks` (pairwise apart and inside `domain`) in place: each round draws radii from
/// `radii`, inserts disks of them where the packing has the most room (insertion.hpp), and relaxes
/// every overlap away;
/// a round that cannot be relaxed within its steps is undone and the next inserts half as many.
/// Ends when a round of a few per ten thousand disks fails. The disks stay in their polygons (none
/// crosses a wall), the drawn radii are kept, and the result goes to the certifier. `clearance`:
/// the generators' (the relaxation keeps 4 of them between disks). Deterministic for `rng`'s
/// state. Returns its rounds, insertions, steps and time. `tick` (may be empty) is called
/// with the disks and the fraction of the rounds done every 64 relaxation steps and after each
/// round; once it returns false the round under way is undone and the report says cancelled.
/// Never makes more than max_disks disks (FillOptions::max_disks). Throws CancelledError once
/// `stop` is requested.
JamReport jam(const Domain& domain, const RadiusDistribution& radii, double clearance, std::size_t max_disks, Rng& rng,
              std::vector<Disk>& disks, const std::function<bool(std::size_t, double)>& tick,
              const std::stop_token& stop);

}  // namespace frontpack::detail
