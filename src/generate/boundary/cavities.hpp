// Cavities: regions of the domain the fronts closed around with no gap or void left facing them.
// A void is lowered to the classes below a radius that failed in it, as if larger radii failed
// too; but a small disk can fail deep in a cusp where a larger one clears the blocker, and a
// cavity's last void then goes out of reach of the radii that fit it (uniform radii 1:10, 207k
// disks: one to three cavities per run that took a disk of the largest size). Once the front is
// done, the boundary front looks for them here and keeps a void facing each (boundary_front.cpp);
// the front resumes there. docs/boundary-method.md, "Cavities".
#pragma once

#include <cstddef>
#include <stop_token>
#include <vector>

#include "generate/boundary/elements.hpp"
#include "generate/boundary/obstacles.hpp"
#include "generate/settings.hpp"

namespace frontpack::detail {

/// The points of a lattice of spacing h over the polygon's box where a disk of radius rmin fits
/// (inside the polygon, clear of every disk and wall), each as the gap between the two disks
/// nearest it whose free side (the left) holds it. A cavity that takes a disk of radius rho holds
/// a lattice point within h / sqrt(2) of that disk's centre, where a disk of radius
/// rho - h / sqrt(2) fits (the clearance of a point is 1-Lipschitz); h = sqrt(2) (rmax - rmin)
/// finds every cavity that takes rmax. The pass runs only where h >= rmax (rmax / rmin >= 3.4), so
/// that it costs about one probe per disk or less: below, the closing rule (boundary_front.cpp)
/// leaves no hole that takes rmax (bidisperse 1:1.4 to uniform 1:3, largest empty circle 0.70-1.00
/// rmax), and a lattice fine enough cost a third of the front. Nothing either if the lattice has
/// more than four points per disk placed (a sliver), or once `stop` is requested.
[[nodiscard]] std::vector<Gap> cavity_gaps(Obstacles& obstacles, const Elements& elements, const RunFrame& frame,
                                           std::size_t placed, const std::stop_token& stop);

}  // namespace frontpack::detail
