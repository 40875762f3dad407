// frontpack: simulator decks, a packing handed over ready to run (LAMMPS, LIGGGHTS, Yade).
//
//   const auto files = frontpack::make_deck(domain, packing.disks, types, {.simulator = Simulator::lammps,
//                                                                        .densities = {2500}});
//   for (const auto& f : files) { /* write f.text to DIR / f.name */ }
//
// A deck is a set of files in memory (the caller writes them, e.g. all-or-nothing through
// OutputFile), that the simulator runs as they are: Debian's `lmp` (LAMMPS 29 Sep 2021),
// `liggghts` (LIGGGHTS-PUBLIC 3.8.0), `yade` (2023.02a). docs/simulators.md describes each file,
// the units, how the stiffness and the timestep are chosen and how the walls are certified.
//
// Walls. LAMMPS has no polygon wall: its deck carries frozen wall disks (wall_disks below).
// LIGGGHTS gets the domain's edges extruded to a triangle mesh (STL), Yade the same as facets.
#pragma once

#include <cstdint>
#include <span>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "frontpack/budget.hpp"
#include "frontpack/domain.hpp"
#include "frontpack/errors.hpp"
#include "frontpack/geometry.hpp"

namespace frontpack {

enum class Simulator : std::uint8_t { lammps, liggghts, yade };

/// "lammps", "liggghts" or "yade".
[[nodiscard]] const char* to_string(Simulator simulator) noexcept;
/// The simulator named `name`; throws OptionError listing the known ones.
[[nodiscard]] Simulator simulator_from_name(std::string_view name);

/// Frozen wall disks outside a domain, for particle-wall codes (LAMMPS).
///
/// Guarantees, for the disks returned:
///   - every wall disk lies in the closure of the domain's complement, decided exactly
///     (Domain::contains on the complement): it cannot overlap any disk that lies in the domain;
///   - along every ring (outer rings and holes), consecutive wall disks (in ring order, cyclically)
///     have centres less than 2 (wall_radius + rmin) apart, so that no free disk of radius >= rmin
///     can pass between them (they leave a gap narrower than its diameter), at convex and reflex
///     corners too.
/// Wall disks have radius `wall_radius` and sit `wall_radius` (1 + 1e-6) from the edges: a gap of
/// 1e-6 wall radii keeps floating-point contact detection in the simulators from seeing a contact
/// with a disk that touches the boundary. These hold on the disks returned: each ring's chain is
/// verified after it is built (outside, no gap, the whole ring covered), not assumed from how it
/// was placed.
///
/// Throws OptionError if a ring cannot be closed so (a hole or a notch narrower than a wall disk:
/// use a smaller wall radius), naming the ring and the place, or if `wall_radius` is below the
/// precision floor of the coordinates (8 ulps of the largest coordinate magnitude / 1e-6: the
/// message names it). Throws LimitError, before any wall disk is placed, if their count (about
/// 2 perimeter / wall_radius, plus corners) exceeds `budget`, naming the smallest radius that fits.
[[nodiscard]] std::vector<Disk> wall_disks(const Domain& domain, double wall_radius, double rmin,
                                           const Budget& budget = {});

/// What a deck sets up. Units are those of the domain and of the densities; with SI inputs (m,
/// kg/m^2 or kg/m^3) the decks use `units si`.
struct DeckOptions {
  Simulator simulator = Simulator::lammps;
  /// Density per type (index type - 1), or one value for every type; each finite and > 0. Mass per
  /// area when thickness is 0, else mass per volume.
  std::vector<double> densities{};
  /// 0: the disks are 2D discs, m = density * pi r^2. > 0: cylinders of this thickness,
  /// m = density * pi r^2 * thickness.
  double thickness = 0;
  double gravity = 9.81;  ///< magnitude, along -y
  /// Wall disks' radius (LAMMPS); 0: the packing's smallest radius.
  double wall_radius = 0;
  std::uint64_t steps = 5000;  ///< the run's length written into the script
  /// What the deck may make: the wall disks, counted before any is placed.
  Budget budget{};
  std::stop_token stop{};
};

/// Parses a --density spec for `types` types: "2500" (every type) or "1:2500,2:7800" (every type
/// 1..types exactly once). Throws OptionError naming the offending item.
[[nodiscard]] std::vector<double> parse_densities(std::string_view spec, std::uint32_t types);

/// One file of a deck: its name inside the deck's directory and its contents.
struct DeckFile {
  std::string name;
  std::string text;
};

/// The names of the files make_deck writes for `simulator`, in its order.
[[nodiscard]] std::vector<std::string> deck_file_names(Simulator simulator);

/// The deck for `options.simulator`. A periodic domain (Domain::periodic): LAMMPS and LIGGGHTS get
/// the cell as the data file's box and `boundary p p p` (xy) or `boundary p f p` (x, whose bottom
/// and top become wall/gran planes), no wall disks and no mesh; Yade gets `O.periodic = True` with
/// the cell's periods (a shear cell's walls as facets). docs/simulators.md, "Periodic cells". `types` is empty
/// (every disk type 1) or holds one type >= 1 per disk. Throws OptionError (densities, thickness, gravity, walls),
/// LimitError (the wall disks over `options.budget`), CancelledError.
[[nodiscard]] std::vector<DeckFile> make_deck(const Domain& domain, std::span<const Disk> disks,
                                              std::span<const std::uint32_t> types, const DeckOptions& options);

}  // namespace frontpack
