// The Yade deck: the packing as Yade text (with material ids for types) and a script that loads
// it, builds the wall facets from the domain's edges, holds the spheres in the plane and runs.
#include <ostream>
#include <sstream>
#include <stop_token>
#include <string>
#include <vector>

#include "common/format.hpp"
#include "common/stop.hpp"
#include "decks/physics.hpp"
#include "frontpack/io.hpp"
#include "frontpack/version.hpp"

namespace frontpack::detail {

namespace {

// run.py's sections, in order: what it is and the constants, the cell and the walls' rings, the
// materials and the bodies, the engines and the run.

// The header comment, the imports, STEPS, DENSITY and HALF_HEIGHT.
void script_header(std::ostream& py, const DeckOptions& options, const DeckPhysics& p, double young) {
  py << "# Yade script written by frontpack " << version_string
     << " (run: yade -n -x run.py [STEPS], in this directory)\n"
     << "# Loads packing.txt (one material per type, O.materials[type - 1]), builds the walls as facets from\n"
     << "# the domain's edges (vertical quads), holds the spheres in the plane z = 0, applies gravity along -y\n"
     << "# (none in a cell periodic in x and y: no wall would hold the spheres).\n"
     << "# Units: those of the domain and densities (SI: m, kg, s). " << mass_note(options) << ";\n"
     << "# the masses and the (disc) inertia are set per body, since Yade's materials are 3D.\n"
     << "# Contacts: FrictMat, E = kn / rmin = " << format_double(young) << " (kn = " << format_double(p.kn)
     << ", as the LAMMPS deck:\n"
     << "# the weight of a column as tall as the domain presses two smallest disks 1% of rmin deep), friction 0.5,\n"
     << "# non-viscous damping 0.3. Timestep: the contact time of the two lightest disks / 50.\n"
     << "import math\nimport sys\n\nfrom yade import O, utils, ymport\n"
     << "from yade.wrapper import *\n\n"
     << "STEPS = int(sys.argv[1]) if len(sys.argv) > 1 else " << options.steps << "\n"
     << "DENSITY = [";
  for (std::uint32_t t = 0; t < p.types; ++t) {
    py << (t == 0 ? "" : ", ") << format_double(p.area_density[t]);
  }
  py << "]  # mass per area, by type\n"
     << "HALF_HEIGHT = " << format_double(2 * p.rmax) << "  # the facets' extent in z\n";
}

// A periodic cell: CELL, LX, LY, Yade's cell, no rings, and a shear cell's WALLS.
void script_cell(std::ostream& py, const Domain& domain) {
  // Yade's periodic cell wraps all three axes, from the origin: the images of a disk are its
  // translations by the periods whatever the origin, so the cell [xmin, xmax) needs no shift.
  // z: 10 rmax, so that no sphere meets its own image and a facet spans under half of it.
  // A shear cell's y period is its height plus 4 rmax (the walls keep the images apart), and
  // its walls are facets in four pieces per side (a body must span under half of the cell).
  const Box cell = domain.bbox();
  const bool torus = domain.periodicity() == Periodicity::xy;
  py << "CELL = (" << format_double(cell.xmin) << ", " << format_double(cell.ymin) << ", " << format_double(cell.xmax)
     << ", " << format_double(cell.ymax) << ")  # the periodic cell "
     << (torus ? "[xmin, xmax) x [ymin, ymax)\n" : "[xmin, xmax) x [ymin, ymax], walls at ymin and ymax\n")
     << "LX = CELL[2] - CELL[0]\n"
     << "LY = CELL[3] - CELL[1]" << (torus ? "" : " + 2 * HALF_HEIGHT") << "\n"
     << "O.periodic = True\n"
     << "O.cell.setBox(LX, LY, 5 * HALF_HEIGHT)\n";
  if (torus) {
    py << "RINGS = []\n";
  } else {
    py << "RINGS = []\n"
       << "WALLS = [[(CELL[0] + k * LX / 4, y), (CELL[0] + (k + 1) * LX / 4, y)] for y in (CELL[1], CELL[3]) "
          "for k in range(4)]\n";
  }
}

// A domain with walls: RINGS, every ring of the domain as a list of points.
void script_rings(std::ostream& py, const Domain& domain, const std::stop_token& stop) {
  py << "RINGS = [\n";
  for (const Polygon& poly : domain.polygons()) {
    for (std::size_t r = 0; r <= poly.holes.size(); ++r) {
      const Ring& ring = r == 0 ? poly.outer : poly.holes[r - 1];
      py << "    [";
      for (std::size_t i = 0; i < ring.size(); ++i) {
        throw_if_stopped(stop, i);
        py << (i == 0 ? "" : ", ") << '(' << format_double(ring[i].x) << ", " << format_double(ring[i].y) << ')';
      }
      py << "],\n";
    }
  }
}

// The materials (one per type, and the walls'), the spheres held in the plane, and the facets of
// the rings and of a shear cell's walls.
void script_bodies(std::ostream& py, const Domain& domain, double young) {
  py << "for rho in DENSITY:\n"
     << "    O.materials.append(FrictMat(young=" << format_double(young)
     << ", poisson=0.3, frictionAngle=math.atan(0.5), density=rho))\n"
     << "wall_material = O.materials.append(FrictMat(young=" << format_double(young)
     << ", poisson=0.3, frictionAngle=math.atan(0.5), density=1))\n"
     << "spheres = ymport.textExt('packing.txt')\n"
     << "for s in spheres:\n"
     << "    r = s.shape.radius\n"
     << "    s.state.mass = DENSITY[s.material.id] * math.pi * r * r\n"
     << "    i = 0.5 * s.state.mass * r * r\n"
     << "    s.state.inertia = (i, i, i)\n"
     << "    s.state.blockedDOFs = 'zXY'\n"
     << "O.bodies.append(spheres)\n"
     << "for ring in RINGS:\n"
     << "    for k in range(len(ring)):\n"
     << "        (ax, ay), (bx, by) = ring[k], ring[(k + 1) % len(ring)]\n"
     << "        a0, b0 = (ax, ay, -HALF_HEIGHT), (bx, by, -HALF_HEIGHT)\n"
     << "        a1, b1 = (ax, ay, HALF_HEIGHT), (bx, by, HALF_HEIGHT)\n"
     << "        O.bodies.append(utils.facet([a0, b0, b1], fixed=True, material=wall_material))\n"
     << "        O.bodies.append(utils.facet([a0, b1, a1], fixed=True, material=wall_material))\n";
  if (domain.periodicity() == Periodicity::x) {
    py << "for (ax, ay), (bx, by) in WALLS:\n"
       << "    a0, b0 = (ax, ay, -HALF_HEIGHT), (bx, by, -HALF_HEIGHT)\n"
       << "    a1, b1 = (ax, ay, HALF_HEIGHT), (bx, by, HALF_HEIGHT)\n"
       << "    O.bodies.append(utils.facet([a0, b0, b1], fixed=True, material=wall_material))\n"
       << "    O.bodies.append(utils.facet([a0, b1, a1], fixed=True, material=wall_material))\n";
  }
}

// The engines, the run (in a periodic cell, the contacts after the first step are printed) and
// the final state written to final.txt.
void script_run(std::ostream& py, const Domain& domain, const DeckPhysics& p) {
  const bool periodic = domain.periodicity() != Periodicity::none;
  py << "\n"
     << "O.engines = [\n"
     << "    ForceResetter(),\n"
     << "    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),\n"
     << "    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],\n"
     << "                    [Ip2_FrictMat_FrictMat_FrictPhys()],\n"
     << "                    [Law2_ScGeom_FrictPhys_CundallStrack()]),\n"
     // No gravity in a torus: no wall holds the spheres, and it would carry the whole packing along.
     << "    NewtonIntegrator(damping=0.3, gravity=(0, "
     << format_double(domain.periodicity() == Periodicity::xy ? 0.0 : -p.gravity) << ", 0)),\n"
     << "]\n"
     << "O.dt = " << format_double(p.dt_hooke) << "\n"
     << (periodic ? "O.run(1, True)\n"
                    "# Contacts after the first step: 0 for a certified packing (across the periodic sides too).\n"
                    "print('FRONTPACK_START_CONTACTS %d' % sum(1 for i in O.interactions if i.isReal))\n"
                    "if STEPS > 1:\n"
                    "    O.run(STEPS - 1, True)\n"
                  : "O.run(STEPS, True)\n")
     << "with open('final.txt', 'w') as f:\n"
     << "    for b in O.bodies:\n"
     << "        if isinstance(b.shape, Sphere):\n"
     << "            f.write('%r %r %r %d\\n' % (b.state.pos[0], b.state.pos[1], b.shape.radius, b.material.id + 1))\n"
     << "print('FRONTPACK_DONE %d steps, %d spheres' % (O.iter, len(spheres)))\n";
}

}  // namespace

std::vector<DeckFile> yade_deck(const Domain& domain, std::span<const Disk> disks, std::span<const std::uint32_t> types,
                                const DeckOptions& options, const DeckPhysics& p) {
  std::vector<std::uint32_t> all_types(types.begin(), types.end());
  if (all_types.empty()) {
    all_types.assign(disks.size(), 1);
  }
  std::ostringstream packing;
  write_yade(packing, disks, all_types, options.stop);

  // Yade's FrictPhys gives kn = 2 E1 r1 E2 r2 / (E1 r1 + E2 r2): E r for two equal radii r, so
  // E = kn / rmin gives the two smallest disks the stiffness of the LAMMPS deck.
  const double young = p.kn / p.rmin;
  std::ostringstream py;
  script_header(py, options, p, young);
  if (domain.periodicity() != Periodicity::none) {
    script_cell(py, domain);
    py << "\n";
  } else {
    script_rings(py, domain, options.stop);
    py << "]\n\n";
  }
  script_bodies(py, domain, young);
  script_run(py, domain, p);
  return {{"packing.txt", packing.str()}, {"run.py", py.str()}};
}

}  // namespace frontpack::detail
