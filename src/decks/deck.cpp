// Decks: simulator names, density specs, the physical parameters every deck shares, dispatch.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/format.hpp"
#include "common/numbers.hpp"
#include "common/text.hpp"
#include "decks/physics.hpp"

namespace frontpack {

namespace {

double parse_positive(std::string_view text, const std::string& what) {
  const detail::Decimal d = detail::parse_decimal(text);
  if (d.status != detail::DecimalStatus::ok || !std::isfinite(d.value) || !(d.value > 0)) {
    throw OptionError(what + " " + detail::quote_text(text) + " is not a finite number > 0");
  }
  return d.value;
}

}  // namespace

const char* to_string(Simulator simulator) noexcept {
  switch (simulator) {
    case Simulator::lammps: return "lammps";
    case Simulator::liggghts: return "liggghts";
    case Simulator::yade: return "yade";
  }
  return "unknown";
}

Simulator simulator_from_name(std::string_view name) {
  for (const Simulator s : {Simulator::lammps, Simulator::liggghts, Simulator::yade}) {
    if (name == to_string(s)) {
      return s;
    }
  }
  throw OptionError("unknown simulator " + detail::quote_text(name) + "; expected lammps, liggghts or yade");
}

std::vector<std::string> deck_file_names(Simulator simulator) {
  switch (simulator) {
    case Simulator::lammps: return {"deck.data", "in.frontpack", "domain.wkt"};
    case Simulator::liggghts: return {"deck.data", "walls.stl", "in.frontpack", "domain.wkt"};
    case Simulator::yade: return {"packing.txt", "run.py", "domain.wkt"};
  }
  return {};
}

std::vector<double> parse_densities(std::string_view spec, std::uint32_t types) {
  if (spec.find(':') == std::string_view::npos) {
    return std::vector<double>(types, parse_positive(spec, "density"));
  }
  std::vector<double> out(types, 0.0);
  for (const std::string_view item : detail::split(spec, ',')) {
    const std::size_t colon = item.find(':');
    const std::string_view t = item.substr(0, colon);
    std::uint32_t type = 0;
    const bool digits = !t.empty() && t.size() < 10 && t.find_first_not_of("0123456789") == std::string_view::npos;
    for (const char c : digits ? t : std::string_view{}) {
      type = type * 10 + static_cast<std::uint32_t>(c - '0');
    }
    if (colon == std::string_view::npos || !digits || type < 1 || type > types) {
      throw OptionError("density " + detail::quote_text(item) + ": expected TYPE:DENSITY with TYPE from 1 to " +
                        std::to_string(types) + " (the number of types)");
    }
    if (out[type - 1] != 0) {
      throw OptionError("density of type " + std::to_string(type) + " given twice in " + detail::quote_text(spec));
    }
    out[type - 1] = parse_positive(item.substr(colon + 1), "density of type " + std::to_string(type));
  }
  for (std::uint32_t t = 0; t < types; ++t) {
    if (out[t] == 0) {
      throw OptionError("no density for type " + std::to_string(t + 1) + " in " + detail::quote_text(spec) +
                        " (give every type, or one density for all)");
    }
  }
  return out;
}

namespace detail {

std::string mass_note(const DeckOptions& options) {
  return options.thickness > 0 ? "densities are per volume; each disk is a cylinder of thickness " +
                                     format_double(options.thickness) + ": mass = density * pi r^2 * thickness"
                               : std::string("densities are per area (2D discs): mass = density * pi r^2");
}

DeckPhysics deck_physics(const Domain& domain, std::span<const Disk> disks, std::span<const std::uint32_t> types,
                         const DeckOptions& options) {
  if (disks.empty()) {
    throw OptionError("a deck needs at least one disk");
  }
  if (!types.empty() && types.size() != disks.size()) {
    throw OptionError("deck: " + std::to_string(types.size()) + " types for " + std::to_string(disks.size()) +
                      " disks (expected one type per disk)");
  }
  if (!(std::isfinite(options.thickness) && options.thickness >= 0)) {
    throw OptionError("thickness " + format_double(options.thickness) + " must be a finite number >= 0");
  }
  if (!(std::isfinite(options.gravity) && options.gravity > 0)) {
    throw OptionError("gravity " + format_double(options.gravity) + " must be a finite number > 0");
  }
  if (options.steps < 1) {
    throw OptionError("a deck runs at least 1 step");
  }
  DeckPhysics p;
  // The types: 1 .. the largest type of a disk, or more where one density per type is given
  // (a size class no disk fell in keeps its type number).
  const std::uint32_t largest = types.empty() ? 1 : *std::max_element(types.begin(), types.end());
  if (largest < 1 || (!types.empty() && *std::min_element(types.begin(), types.end()) < 1)) {
    throw OptionError("deck: types are >= 1");
  }
  p.types = std::max(largest, static_cast<std::uint32_t>(options.densities.size()));
  if (options.densities.size() != 1 && options.densities.size() != p.types) {
    throw OptionError("deck: " + std::to_string(options.densities.size()) + " densities for " +
                      std::to_string(p.types) + " types (give one for all, or one per type)");
  }
  for (std::uint32_t t = 0; t < p.types; ++t) {
    const double rho = options.densities.size() == 1 ? options.densities[0] : options.densities[t];
    if (!(std::isfinite(rho) && rho > 0)) {
      throw OptionError("density " + format_double(rho) + " of type " + std::to_string(t + 1) +
                        " must be a finite number > 0");
    }
    p.area_density.push_back(options.thickness > 0 ? rho * options.thickness : rho);
  }
  p.rmin = p.rmax = disks[0].radius;
  p.mass_min = INFINITY;
  p.mass_max = 0;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const double r = disks[i].radius;
    p.rmin = std::min(p.rmin, r);
    p.rmax = std::max(p.rmax, r);
    const double m = p.area_density[(types.empty() ? 1 : types[i]) - 1] * std::numbers::pi * r * r;
    p.mass_min = std::min(p.mass_min, m);
    p.mass_max = std::max(p.mass_max, m);
  }
  const double rho_max = *std::max_element(p.area_density.begin(), p.area_density.end());
  p.height = domain.bbox().height();
  p.gravity = options.gravity;
  // The weight of a column as tall as the domain and one largest disk wide rests on a contact at
  // the bottom: it may press that contact 1% of the smallest radius deep.
  p.load = rho_max * p.gravity * p.height * 2 * p.rmax;
  p.overlap = 0.01 * p.rmin;
  p.kn = p.load / p.overlap;
  // Contact time of the two lightest disks (effective mass m/2), a 50th of it per step.
  const double m_eff = p.mass_min / 2;
  p.dt_hooke = std::numbers::pi * std::sqrt(m_eff / p.kn) / 50;
  // Damping ratio for restitution e = 0.5, exact for the two heaviest disks (lighter pairs are
  // damped less, since gran/hooke's damping force is m_eff gamma_n v_n).
  const double ln_e = std::log(2.0);
  const double zeta = ln_e / std::sqrt(std::numbers::pi * std::numbers::pi + ln_e * ln_e);
  p.gamma_n = 2 * zeta * std::sqrt(p.kn / (p.mass_max / 2));
  // Hertz (LIGGGHTS): F = 4/3 E* sqrt(R*) d^1.5 with R* = rmin / 2, E* = E / (2 (1 - nu^2)).
  const double r_eff = p.rmin / 2;
  const double e_star = 3 * p.load / (4 * std::sqrt(r_eff) * std::pow(p.overlap, 1.5));
  p.hertz_modulus = 2 * (1 - 0.3 * 0.3) * e_star;
  const double k_hertz = 2 * e_star * std::sqrt(r_eff * p.overlap);  // dF/dd at the design overlap
  p.dt_hertz = std::numbers::pi * std::sqrt(m_eff / k_hertz) / 50;
  return p;
}

}  // namespace detail

std::vector<DeckFile> make_deck(const Domain& domain, std::span<const Disk> disks, std::span<const std::uint32_t> types,
                                const DeckOptions& options) {
  const detail::DeckPhysics physics = detail::deck_physics(domain, disks, types, options);
  std::vector<DeckFile> files;
  switch (options.simulator) {
    case Simulator::lammps: files = detail::lammps_deck(domain, disks, types, options, physics); break;
    case Simulator::liggghts: files = detail::liggghts_deck(domain, disks, types, options, physics); break;
    case Simulator::yade: files = detail::yade_deck(domain, disks, types, options, physics); break;
  }
  // The domain the packing was certified in (a CAD file's curves already made polylines), so that
  // the state after a run can be checked against it: frontpack check DIR/domain.wkt DUMP.
  files.push_back({"domain.wkt", domain.to_wkt() + "\n"});
  return files;
}

}  // namespace frontpack
