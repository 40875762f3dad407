// The LAMMPS deck: a data file with the packed disks and frozen wall disks, and an input script.
#include <algorithm>
#include <sstream>
#include <string>

#include "common/format.hpp"
#include "decks/physics.hpp"
#include "frontpack/io.hpp"
#include "frontpack/version.hpp"

namespace frontpack::detail {

namespace {

// The script's end, the same for walled and periodic decks: gravity on the free disks (unless
// `gravity` is false), 2D integration, the timestep, thermo output, the 17-digit dump and the run.
void write_motion_and_run(std::ostream& in, const DeckPhysics& p, std::uint64_t steps, bool gravity) {
  const std::uint64_t every = std::max<std::uint64_t>(1, steps / 10);
  if (gravity) {
    in << "fix gravity free gravity " << format_double(p.gravity) << " vector 0 -1 0\n";
  }
  in << "fix move free nve/sphere disc\n"
     << "fix plane all enforce2d\n"
     << "# Timestep: the contact time pi sqrt(m_eff / kn) of the two lightest disks (m_eff = "
     << format_double(p.mass_min / 2) << ") / 50.\n"
     << "timestep " << format_double(p.dt_hooke) << "\n"
     << "compute ke free ke\n"
     << "thermo_style custom step atoms c_ke\n"
     << "thermo " << every << "\n"
     << "dump free free custom " << every << " free.lammpstrj id type radius mass x y vx vy fx fy\n"
     << "dump_modify free sort id format float %.17g\n"
     << "run " << steps << "\n";
}

// A periodic cell: the box is the cell itself (boundary p p p, or p f p with the shear cell's
// walls as two frictional wall planes at ymin and ymax, fix wall/gran: exact flat walls, no wall
// disks); no wall disks in a periodic direction.
std::vector<DeckFile> periodic_lammps_deck(const Domain& domain, std::span<const Disk> disks,
                                           std::span<const std::uint32_t> types, const DeckOptions& options,
                                           const DeckPhysics& p) {
  const Box cell = domain.bbox();
  const bool torus = domain.periodicity() == Periodicity::xy;
  std::vector<std::uint32_t> all_types(disks.size(), 1);
  if (!types.empty()) {
    std::copy(types.begin(), types.end(), all_types.begin());
  }
  LammpsOptions data_options;
  data_options.type_densities = p.area_density;
  data_options.atom_types = p.types;
  data_options.periodicity = domain.periodicity();
  std::ostringstream data;
  write_lammps(data, disks, all_types, cell, data_options, options.stop);

  const std::string free_types = p.types == 1 ? std::string("1") : "1.." + std::to_string(p.types);
  const std::string cell_text = format_double(cell.xmin) + "," + format_double(cell.ymin) + "," +
                                format_double(cell.xmax) + "," + format_double(cell.ymax);
  std::ostringstream in;
  in << "# LAMMPS input written by frontpack " << version_string << " (run: lmp -in in.frontpack)\n"
     << "# " << disks.size() << " disks of types " << free_types << " in the periodic cell ["
     << format_double(cell.xmin) << ", " << format_double(cell.xmax) << ") x [" << format_double(cell.ymin) << ", "
     << format_double(cell.ymax) << (torus ? ")" : "]") << ",\n"
     << (torus ? "# periodic in x and y (the data file's box is the cell).\n"
               : "# periodic in x; the bottom and top are frictional wall planes (fix wall/gran).\n")
     << "# Certify a snapshot: frontpack check --periodic " << cell_text << " --periodic-axes " << (torus ? "xy" : "x")
     << " free.lammpstrj --timestep 0\n"
     << "# Units: those of the domain and densities (SI: m, kg, s). " << mass_note(options) << ".\n"
     << "units si\n"
     << "dimension 2\n"
     << "atom_style sphere\n"
     << (torus ? "boundary p p p\n" : "boundary p f p\n") << "newton off\n"
     << "comm_modify vel yes\n"
     << "read_data deck.data\n"
     << "group free type " << (p.types == 1 ? std::string("1") : "1:" + std::to_string(p.types)) << "\n";
  for (std::uint32_t t = 1; t <= p.types; ++t) {
    in << "set type " << t << " density/disc " << format_double(p.area_density[t - 1]) << "\n";
  }
  in << "# Hooke contacts. kn = F / d: F = " << format_double(p.load)
     << " is the weight of a column as tall as the cell\n"
     << "# and 2 rmax wide (density * g * height * 2 rmax), d = " << format_double(p.overlap)
     << " is 1% of rmin. kt = 2/7 kn; gamman gives\n"
     << "# restitution 0.5 for the two heaviest disks; gammat = gamman / 2; friction 0.5.\n"
     << "pair_style gran/hooke/history " << format_double(p.kn) << " NULL " << format_double(p.gamma_n)
     << " NULL 0.5 1\n"
     << "pair_coeff * *\n"
     << "neighbor " << format_double(0.5 * p.rmin) << " bin\n"
     << "neigh_modify delay 0 every 1 check yes\n";
  if (!torus) {
    in << "fix walls free wall/gran hooke/history " << format_double(p.kn) << " NULL " << format_double(p.gamma_n)
       << " NULL 0.5 1 yplane " << format_double(cell.ymin) << ' ' << format_double(cell.ymax) << "\n";
  }
  if (torus) {
    in << "# No gravity: in a torus no wall holds the disks, and gravity would carry the whole packing along\n"
          "# at once.\n";
  }
  write_motion_and_run(in, p, options.steps, !torus);
  return {{"deck.data", data.str()}, {"in.frontpack", in.str()}};
}

}  // namespace

std::vector<DeckFile> lammps_deck(const Domain& domain, std::span<const Disk> disks,
                                  std::span<const std::uint32_t> types, const DeckOptions& options,
                                  const DeckPhysics& p) {
  if (domain.periodicity() != Periodicity::none) {
    return periodic_lammps_deck(domain, disks, types, options, p);
  }
  const double wall_radius = options.wall_radius > 0 ? options.wall_radius : p.rmin;
  const std::vector<Disk> walls = wall_disks(domain, wall_radius, p.rmin, options.budget);
  const std::uint32_t wall_type = p.types + 1;

  std::vector<Disk> all(disks.begin(), disks.end());
  all.insert(all.end(), walls.begin(), walls.end());
  std::vector<std::uint32_t> all_types(disks.size(), 1);
  if (!types.empty()) {
    std::copy(types.begin(), types.end(), all_types.begin());
  }
  all_types.resize(all.size(), wall_type);
  Box box;
  for (const Disk& d : all) {
    box.extend(Box{d.centre.x - d.radius, d.centre.y - d.radius, d.centre.x + d.radius, d.centre.y + d.radius});
  }
  // Room around the walls, so that rounding in LAMMPS's box never loses a wall atom.
  const double margin = 2 * p.rmax;
  box = Box{box.xmin - margin, box.ymin - margin, box.xmax + margin, box.ymax + margin};

  LammpsOptions data_options;
  data_options.type_densities = p.area_density;
  data_options.type_densities.push_back(*std::max_element(p.area_density.begin(), p.area_density.end()));
  data_options.atom_types = wall_type;
  std::ostringstream data;
  write_lammps(data, all, all_types, box, data_options, options.stop);

  const std::string free_types = p.types == 1 ? std::string("1") : "1.." + std::to_string(p.types);
  const std::string w = std::to_string(wall_type);
  std::ostringstream in;
  in << "# LAMMPS input written by frontpack " << version_string << " (run: lmp -in in.frontpack)\n"
     << "# " << disks.size() << " free disks of types " << free_types << ", " << walls.size()
     << " frozen wall disks of type " << w << " (radius " << format_double(wall_radius) << ")\n"
     << "# outside the domain along every edge and hole: each lies in the closure of the domain's complement\n"
     << "# (certified exactly) and neighbours leave no gap a disk of radius " << format_double(p.rmin)
     << " could pass.\n"
     << "# Units: those of the domain and densities (SI: m, kg, s). " << mass_note(options) << ".\n"
     << "units si\n"
     << "dimension 2\n"
     << "atom_style sphere\n"
     << "boundary f f p\n"
     << "newton off\n"
     << "comm_modify vel yes\n"
     << "read_data deck.data\n"
     << "group wall type " << w << "\n"
     << "group free subtract all wall\n";
  for (std::uint32_t t = 1; t <= p.types; ++t) {
    in << "set type " << t << " density/disc " << format_double(p.area_density[t - 1]) << "\n";
  }
  in << "# Hooke contacts. kn = F / d: F = " << format_double(p.load)
     << " is the weight of a column as tall as the domain\n"
     << "# and 2 rmax wide (density * g * height * 2 rmax), d = " << format_double(p.overlap)
     << " is 1% of rmin. kt = 2/7 kn; gamman gives\n"
     << "# restitution 0.5 for the two heaviest disks (lighter pairs are damped less); gammat = gamman / 2;\n"
     << "# friction 0.5.\n"
     << "pair_style gran/hooke/history " << format_double(p.kn) << " NULL " << format_double(p.gamma_n)
     << " NULL 0.5 1\n"
     << "pair_coeff * *\n"
     << "neighbor " << format_double(0.5 * p.rmin) << " bin\n"
     << "neigh_modify delay 0 every 1 check yes exclude type " << w << ' ' << w << "\n"
     << "fix walls wall freeze\n";
  write_motion_and_run(in, p, options.steps, true);
  return {{"deck.data", data.str()}, {"in.frontpack", in.str()}};
}

}  // namespace frontpack::detail
