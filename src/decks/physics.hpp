// What every deck shares: masses from the densities, and the contact stiffness, damping and
// timestep chosen from the radii, the densities, gravity and the domain's height
// (docs/simulators.md, "Stiffness and timestep").
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "frontpack/deck.hpp"

namespace frontpack::detail {

struct DeckPhysics {
  std::uint32_t types = 1;             ///< free particle types 1..types; walls are type types + 1
  std::vector<double> area_density{};  ///< mass per area of each type (index type - 1)
  double rmin = 0;
  double rmax = 0;
  double height = 0;         ///< the domain's height (its bounding box's)
  double gravity = 0;        ///< magnitude, along -y
  double load = 0;           ///< F: weight of a column of the domain's height and 2 rmax wide
  double overlap = 0;        ///< the overlap F causes: 1% of rmin
  double kn = 0;             ///< Hooke normal stiffness F / overlap (LAMMPS, Yade)
  double gamma_n = 0;        ///< LAMMPS gran/hooke damping (1/time): restitution 0.5 for two largest-mass disks
  double hertz_modulus = 0;  ///< LIGGGHTS Hertz: Young's modulus (Poisson 0.3) giving the same overlap
  double dt_hooke = 0;       ///< t_c / 50 for the two lightest disks under kn
  double dt_hertz = 0;       ///< t_c / 50 for the two lightest disks at the Hertz stiffness at `overlap`
  double mass_min = 0;
  double mass_max = 0;
};

/// Validates the options and computes the parameters. Throws OptionError.
[[nodiscard]] DeckPhysics deck_physics(const Domain& domain, std::span<const Disk> disks,
                                       std::span<const std::uint32_t> types, const DeckOptions& options);

/// A sentence for the scripts' comments: how the masses were set.
[[nodiscard]] std::string mass_note(const DeckOptions& options);

[[nodiscard]] std::vector<DeckFile> lammps_deck(const Domain& domain, std::span<const Disk> disks,
                                                std::span<const std::uint32_t> types, const DeckOptions& options,
                                                const DeckPhysics& physics);
[[nodiscard]] std::vector<DeckFile> liggghts_deck(const Domain& domain, std::span<const Disk> disks,
                                                  std::span<const std::uint32_t> types, const DeckOptions& options,
                                                  const DeckPhysics& physics);
[[nodiscard]] std::vector<DeckFile> yade_deck(const Domain& domain, std::span<const Disk> disks,
                                              std::span<const std::uint32_t> types, const DeckOptions& options,
                                              const DeckPhysics& physics);

}  // namespace frontpack::detail
