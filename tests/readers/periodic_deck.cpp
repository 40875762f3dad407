// Writes a dense periodic packing and its deck, for the test that runs the deck in the real
// LAMMPS, LIGGGHTS or Yade (check_periodic_deck.py):
//   frontpack_periodic_deck lammps|liggghts|yade xy|x clean|overlap OUTDIR
// -> OUTDIR/packing.csv (x,y,r,type), OUTDIR/deck/ (make_deck, 1000 steps); prints the cell as
// XMIN,YMIN,XMAX,YMAX on the first line, and for `overlap` the planted pair "I J" on the second.
// The packing is fill()'s closed form in the periodic cell, bidisperse 1:1.4 (types 1 and 2 by
// size), certified by fill. `overlap` moves the disk nearest to the left side across the seam
// into its nearest image neighbour by 1% of rmin: the test's checks must see it.
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace fp = frontpack;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: frontpack_periodic_deck lammps|liggghts|yade xy|x clean|overlap OUTDIR\n";
    return 1;
  }
  try {
    const fp::Simulator simulator = fp::simulator_from_name(argv[1]);
    const bool torus = std::string(argv[2]) == "xy";
    const bool overlap = std::string(argv[3]) == "overlap";
    // Bounds that are not round numbers: the periods are not doubles' exact differences of 0.
    const fp::Box cell{0.1, -0.03, 0.1 + 0.24, -0.03 + 0.18};
    const fp::Domain domain = fp::Domain::periodic(cell, torus ? fp::Periodicity::xy : fp::Periodicity::x);
    fp::FillOptions options;
    options.method = fp::Method::closed;
    options.radii = fp::parse_radii("discrete:0.004:0.5,0.0056:0.5");
    options.seed = 4;
    std::vector<fp::Disk> disks = fp::fill(domain, options).disks;
    std::vector<std::uint32_t> types;
    for (const fp::Disk& d : disks) {
      types.push_back(d.radius > 0.0048 ? 2 : 1);
    }
    const fp::CertifyReport report = fp::certify(domain, disks);
    if (!report.outside.empty() || !report.overlapping.empty() || disks.size() < 400) {
      std::cerr << "frontpack_periodic_deck: the fill is not certified, or too small\n";
      return 2;
    }
    std::string planted;
    if (overlap) {
      // The disk nearest the left side, and its nearest neighbour through the seam (minimum image).
      const double lx = cell.xmax - cell.xmin;
      const double ly = cell.ymax - cell.ymin;
      std::size_t i = 0;
      for (std::size_t k = 1; k < disks.size(); ++k) {
        if (disks[k].centre.x < disks[i].centre.x) {
          i = k;
        }
      }
      std::size_t j = i;
      double best = std::numeric_limits<double>::infinity();
      double dx_best = 0;
      double dy_best = 0;
      for (std::size_t k = 0; k < disks.size(); ++k) {
        const double dx = disks[i].centre.x - (disks[k].centre.x - lx);
        double dy = disks[i].centre.y - disks[k].centre.y;
        if (torus) {
          dy -= ly * std::round(dy / ly);
        }
        const double gap = std::hypot(dx, dy) - disks[i].radius - disks[k].radius;
        if (k != i && gap < best) {
          best = gap;
          j = k;
          dx_best = dx;
          dy_best = dy;
        }
      }
      const double length = std::hypot(dx_best, dy_best);
      const double move = best + 0.01 * 0.004;
      disks[i].centre.x -= move * dx_best / length;
      disks[i].centre.y -= move * dy_best / length;
      if (disks[i].centre.x < cell.xmin) {
        disks[i].centre.x += lx;
      }
      if (torus && disks[i].centre.y < cell.ymin) {
        disks[i].centre.y += ly;
      }
      const fp::CertifyReport planted_report = fp::certify(domain, disks);
      if (planted_report.overlapping.empty() || !planted_report.outside.empty()) {
        std::cerr << "frontpack_periodic_deck: the planted overlap was not made\n";
        return 2;
      }
      planted = std::to_string(std::min(i, j)) + " " + std::to_string(std::max(i, j));
    }
    const std::filesystem::path dir = argv[4];
    std::filesystem::create_directories(dir / "deck");
    fp::WriteOptions write;
    write.types = types;
    fp::write_file(dir / "packing.csv", fp::Format::csv, domain, disks, write);
    fp::DeckOptions deck;
    deck.simulator = simulator;
    deck.densities = {2500, 7800};
    deck.steps = 1000;
    for (const fp::DeckFile& f : fp::make_deck(domain, disks, types, deck)) {
      std::ofstream(dir / "deck" / f.name) << f.text;
    }
    std::cout.precision(17);
    std::cout << cell.xmin << "," << cell.ymin << "," << cell.xmax << "," << cell.ymax << "\n" << planted << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "frontpack_periodic_deck: " << e.what() << "\n";
    return 2;
  }
}
