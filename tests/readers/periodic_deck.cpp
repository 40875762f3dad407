// Writes a dense periodic packing and its LAMMPS deck, for the test that runs the deck in the real
// LAMMPS (check_periodic_deck.py): frontpack_periodic_deck xy|x clean|overlap OUTDIR
// -> OUTDIR/packing.csv (x,y,r,type), OUTDIR/deck/ (make_deck, 1000 steps); prints the cell as
// XMIN,YMIN,XMAX,YMAX. The packing is a hexagonal lattice of bidisperse disks (radii 0.48 and 0.34
// of the spacing, one disk in three small), shifted so that rows and columns cross the periodic
// sides, certified exactly before it is written. `overlap` moves one disk on the left side across
// the seam into its neighbour's image by 1% of a radius: the test's checks must see it.
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: frontpack_periodic_deck xy|x clean|overlap OUTDIR\n";
    return 1;
  }
  try {
    const bool torus = std::string(argv[1]) == "xy";
    const bool overlap = std::string(argv[2]) == "overlap";
    const double a = 0.01;  // lattice spacing, m
    const double row = a * std::sqrt(3.0) / 2;
    const int nx = 24;
    const int ny = 20;  // even: the lattice is periodic in y
    const double big = 0.48 * a;
    const double small = 0.34 * a;
    // Origin away from 0, so that the cell's bounds are not round numbers.
    const double x0 = 0.1;
    const double y0 = -0.03;
    const fp::Box cell{x0, y0, x0 + nx * a, torus ? y0 + ny * row : y0 + (ny - 1) * row + 2 * big * 1.01};
    std::vector<fp::Disk> disks;
    std::vector<std::uint32_t> types;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const bool is_small = (i + 2 * j) % 3 == 0;
        double x = x0 + (i + 0.5 * (j % 2) + 0.3) * a;
        double y = torus ? y0 + (j + 0.2) * row : y0 + big * 1.01 + j * row;
        if (x >= cell.xmax) {
          x -= cell.xmax - cell.xmin;
        }
        if (torus && y >= cell.ymax) {
          y -= cell.ymax - cell.ymin;
        }
        disks.push_back({{x, y}, is_small ? small : big});
        types.push_back(is_small ? 2 : 1);
      }
    }
    const fp::Domain domain = fp::Domain::periodic(cell, torus ? fp::Periodicity::xy : fp::Periodicity::x);
    const fp::CertifyReport report = fp::certify(domain, disks);
    if (!report.outside.empty() || !report.overlapping.empty()) {
      std::cerr << "frontpack_periodic_deck: the lattice is not certified\n";
      return 2;
    }
    if (overlap) {
      // Disk 0 sits 0.3 a right of the left side; the last disk of row 0 is its left neighbour
      // through the seam (a apart). Move disk 0 left until it overlaps that image by 1% of rmin.
      const fp::Disk& left = disks[nx - 1];
      const double gap = a - disks[0].radius - left.radius;
      disks[0].centre.x -= gap + 0.01 * small;
      if (disks[0].centre.x < cell.xmin) {
        disks[0].centre.x += cell.xmax - cell.xmin;
      }
      if (fp::certify(domain, disks).overlapping.empty()) {
        std::cerr << "frontpack_periodic_deck: the planted overlap was not made\n";
        return 2;
      }
    }
    const std::filesystem::path dir = argv[3];
    std::filesystem::create_directories(dir / "deck");
    fp::WriteOptions options;
    options.types = types;
    fp::write_file(dir / "packing.csv", fp::Format::csv, domain, disks, options);
    fp::DeckOptions deck;
    deck.simulator = fp::Simulator::lammps;
    deck.densities = {2500, 7800};
    deck.steps = 1000;
    for (const fp::DeckFile& f : fp::make_deck(domain, disks, types, deck)) {
      std::ofstream(dir / "deck" / f.name) << f.text;
    }
    std::cout.precision(17);
    std::cout << cell.xmin << "," << cell.ymin << "," << cell.xmax << "," << cell.ymax << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "frontpack_periodic_deck: " << e.what() << "\n";
    return 2;
  }
}
