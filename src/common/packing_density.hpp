// The packing fractions the estimates assume. Neither is a result: the certifier never reads
// them, and a run that packs denser or looser is still correct; they size reservations, the
// limits checked before a run, progress, and when the boundary front stops seeding.
#pragma once

namespace frontpack::detail {

/// What a random dense packing of disks covers of an area (the paper, Sec. 4, and our
/// measurements on the shapes).
inline constexpr double kRandomDenseFraction = 0.82;

/// The fraction the disk-count estimate assumes (estimate_disks(), and the progress it is the
/// scale of): a little above kRandomDenseFraction, near the jammed packings of the usual radius
/// ratios (0.84-0.85), so that the estimate errs on the side of more disks: reservations rarely
/// grow, and the limits checked before a run refuse no run that would have fitted.
inline constexpr double kEstimateFraction = 0.85;

}  // namespace frontpack::detail
