// The LIGGGHTS deck: a data file with the packed disks, the domain's edges extruded to an STL
// mesh for fix mesh/surface + fix wall/gran, and an input script (a periodic cell: no mesh).
//
// LIGGGHTS-PUBLIC 3.8.0 (Debian) runs `dimension 2` with `fix enforce2d` and mesh walls, but its
// neighbour lists fail an assertion (region_neighbor_list_I.h) when the periodic z extent is
// about one particle diameter: the box and the mesh are made 20 rmax thick in z, which changes
// nothing for particles held in the plane z = 0.
#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "common/format.hpp"
#include "common/stop.hpp"
#include "decks/physics.hpp"
#include "frontpack/io.hpp"
#include "frontpack/version.hpp"

namespace frontpack::detail {

namespace {

// Every edge as vertical quads (two triangles each) from z = -h to z = h, the edge cut into
// pieces at most 2 h long; facet normals point out of the domain. LIGGGHTS bins the mesh by its
// largest triangle: one much longer than the box is thick fails the same assertion as a thin box.
std::string edge_mesh(const Domain& domain, double h, const std::stop_token& stop) {
  std::ostringstream out;
  const std::string lo = format_double(-h);
  const std::string hi = format_double(h);
  out << "solid frontpack_walls\n";
  std::size_t count = 0;
  for (const Polygon& p : domain.polygons()) {
    for (std::size_t r = 0; r <= p.holes.size(); ++r) {
      const Ring& ring = r == 0 ? p.outer : p.holes[r - 1];
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point a = ring[i];
        const Point b = ring[(i + 1) % ring.size()];
        const std::string normal = format_double(b.y - a.y) + ' ' + format_double(a.x - b.x) + " 0";
        const auto pieces = static_cast<std::size_t>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / (2 * h)));
        const auto at = [&](std::size_t k) {
          if (k == 0) {
            return format_double(a.x) + ' ' + format_double(a.y) + ' ';
          }
          if (k == pieces) {
            return format_double(b.x) + ' ' + format_double(b.y) + ' ';
          }
          const double t = static_cast<double>(k) / static_cast<double>(pieces);
          return format_double(a.x + (b.x - a.x) * t) + ' ' + format_double(a.y + (b.y - a.y) * t) + ' ';
        };
        for (std::size_t k = 0; k < pieces; ++k) {
          throw_if_stopped(stop, count++);
          const std::string u = at(k);
          const std::string v = at(k + 1);
          const auto facet = [&](const std::string& v1, const std::string& v2, const std::string& v3) {
            out << "facet normal " << normal << "\nouter loop\nvertex " << v1 << "\nvertex " << v2 << "\nvertex " << v3
                << "\nendloop\nendfacet\n";
          };
          facet(u + lo, v + lo, v + hi);
          facet(u + lo, v + hi, u + hi);
        }
      }
    }
  }
  out << "endsolid frontpack_walls\n";
  return out.str();
}

std::string repeat(const std::string& value, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    out += ' ' + value;
  }
  return out;
}

// deck.data: the disks as LAMMPS data in `box`, with the wall type as one more atom type, and
// the z range of the top of this file.
std::string deck_data(const Domain& domain, std::span<const Disk> disks, std::span<const std::uint32_t> types,
                      const DeckOptions& options, const DeckPhysics& p, const Box& box) {
  LammpsOptions data_options;
  data_options.type_densities = p.area_density;
  data_options.atom_types = p.types + 1;
  data_options.periodicity = domain.periodicity();
  std::ostringstream data_stream;
  std::vector<std::uint32_t> all_types(types.begin(), types.end());
  if (all_types.empty()) {
    all_types.assign(disks.size(), 1);
  }
  write_lammps(data_stream, disks, all_types, box, data_options, options.stop);
  const double half_z = 10 * p.rmax;
  std::string data = data_stream.str();
  const std::size_t z = data.find(" zlo zhi\n");
  const std::size_t z_start = data.rfind('\n', z) + 1;
  data.replace(z_start, z - z_start, format_double(-half_z) + ' ' + format_double(half_z));
  return data;
}

// in.frontpack's sections, in order: what it is and the simulation's set-up, the contact model
// and the timestep, gravity and the walls, the run.

// The header comment, the atom style, dimension, boundaries, the data file and the neighbour lists.
void input_setup(std::ostream& in, const Domain& domain, std::size_t disks, const DeckOptions& options,
                 const DeckPhysics& p) {
  const bool periodic = domain.periodicity() != Periodicity::none;
  const bool torus = domain.periodicity() == Periodicity::xy;
  const std::string w = std::to_string(p.types + 1);
  in << "# LIGGGHTS input written by frontpack " << version_string << " (run: liggghts -in in.frontpack)\n"
     << "# " << disks << " disks of types 1.." << p.types
     << (!periodic ? "; the domain's edges are the mesh walls.stl (type " + w + ").\n"
         : torus   ? " in the periodic cell (the box).\n"
                   : " in the cell periodic in x (the box); its bottom and top are wall planes (type " + w + ").\n")
     << "# Units: those of the domain and densities (SI: m, kg, s). " << mass_note(options)
     << "\n# (LIGGGHTS's `set density` in 2D sets mass = density * pi r^2).\n"
     << "atom_style granular\n"
     << "atom_modify map array\n"
     << "dimension 2\n"
     << (!periodic ? "boundary f f p\n"
         : torus   ? "boundary p p p\n"
                   : "boundary p f p\n")
     << "newton off\n"
     << "communicate single vel yes\n"
     << "units si\n"
     << "read_data deck.data\n"
     << "neighbor " << format_double(0.5 * p.rmin) << " bin\n"
     << "neigh_modify delay 0\n";
}

// Hertz contacts between every pair of types (the walls' included), the densities and the timestep.
void input_contacts(std::ostream& in, const DeckPhysics& p) {
  const std::size_t n = p.types + 1;  // the disks' types and the walls'
  in << "# Hertz contacts. Young's modulus E (Poisson 0.3) makes F = " << format_double(p.load)
     << ", the weight of a column as tall as the\n"
     << "# domain and 2 rmax wide, press two smallest disks " << format_double(p.overlap)
     << " (1% of rmin) deep: E = 2 (1 - 0.3^2) 3 F / (4 sqrt(rmin/2) d^1.5).\n"
     << "# (LIGGGHTS refuses E > 1e9 in SI units unless told that the particles are hard.)\n"
     << "hard_particles yes\n"
     << "fix m1 all property/global youngsModulus peratomtype" << repeat(format_double(p.hertz_modulus), n) << "\n"
     << "fix m2 all property/global poissonsRatio peratomtype" << repeat("0.3", n) << "\n"
     << "fix m3 all property/global coefficientRestitution peratomtypepair " << n << repeat("0.5", n * n) << "\n"
     << "fix m4 all property/global coefficientFriction peratomtypepair " << n << repeat("0.5", n * n) << "\n"
     << "pair_style gran model hertz tangential history\n"
     << "pair_coeff * *\n";
  for (std::uint32_t t = 1; t <= p.types; ++t) {
    in << "set type " << t << " density " << format_double(p.area_density[t - 1]) << "\n";
  }
  in << "# Timestep: the contact time pi sqrt(m_eff / k) of the two lightest disks (m_eff = "
     << format_double(p.mass_min / 2) << ")\n"
     << "# at the Hertz stiffness k = 2 E* sqrt(R* d) of that overlap, / 50.\n"
     << "timestep " << format_double(p.dt_hertz) << "\n";
}

// Gravity (none in a torus), and the walls: the mesh, or a shear cell's two wall planes.
void input_walls(std::ostream& in, const Domain& domain, const DeckPhysics& p) {
  const bool periodic = domain.periodicity() != Periodicity::none;
  const bool torus = domain.periodicity() == Periodicity::xy;
  const std::string w = std::to_string(p.types + 1);
  const Box b = domain.bbox();
  in << (torus ? "# No gravity: in a torus no wall holds the disks (the whole packing would fall together).\n"
               : "fix gravity all gravity " + format_double(p.gravity) + " vector 0 -1 0\n");
  if (!periodic) {
    in << "fix walls all mesh/surface file walls.stl type " << w << "\n"
       << "fix wall all wall/gran model hertz tangential history mesh n_meshes 1 meshes walls\n";
  } else if (!torus) {
    in << "fix wall all wall/gran model hertz tangential history primitive type " << w << " yplane "
       << format_double(b.ymin) << "\n"
       << "fix wall_top all wall/gran model hertz tangential history primitive type " << w << " yplane "
       << format_double(b.ymax) << "\n";
  }
}

// The integration in the plane, the thermo output, the dump and the run.
void input_run(std::ostream& in, const DeckOptions& options) {
  const std::uint64_t every = std::max<std::uint64_t>(1, options.steps / 10);
  in << "fix move all nve/sphere\n"
     << "fix plane all enforce2d\n"
     << "compute ke all ke\n"
     << "thermo_style custom step atoms c_ke\n"
     << "thermo " << every << "\n"
     << "dump free all custom " << every
     << " free.lammpstrj id type radius mass x y vx vy fx fy\n"
     // LIGGGHTS's dump_modify takes a whole line's format (no "format float"): 17 digits, so that
     // the dump's numbers are the doubles (frontpack check on its first snapshot certifies).
     << "dump_modify free sort id format \"%d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\"\n"
     << "run " << options.steps << "\n";
}

}  // namespace

std::vector<DeckFile> liggghts_deck(const Domain& domain, std::span<const Disk> disks,
                                    std::span<const std::uint32_t> types, const DeckOptions& options,
                                    const DeckPhysics& p) {
  const double half_z = 10 * p.rmax;
  const Box b = domain.bbox();
  const double margin = 2 * p.rmax;
  // A periodic cell is the box itself (boundary p p p, or p f p with the shear cell's walls as
  // two primitive wall planes at ymin and ymax, on the box's faces): no mesh.
  const bool periodic = domain.periodicity() != Periodicity::none;
  const Box box = periodic ? b : Box{b.xmin - margin, b.ymin - margin, b.xmax + margin, b.ymax + margin};
  std::string data = deck_data(domain, disks, types, options, p, box);
  std::ostringstream in;
  input_setup(in, domain, disks.size(), options, p);
  input_contacts(in, p);
  input_walls(in, domain, p);
  input_run(in, options);
  if (periodic) {
    return {{"deck.data", std::move(data)}, {"in.frontpack", in.str()}};
  }
  return {{"deck.data", std::move(data)},
          {"walls.stl", edge_mesh(domain, 0.9 * half_z, options.stop)},
          {"in.frontpack", in.str()}};
}

}  // namespace frontpack::detail
