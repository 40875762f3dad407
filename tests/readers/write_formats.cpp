// Writes one real packing in every disk format, for the tests that read it back with the real
// programs (LAMMPS, VTK, Yade): frontpack_write_formats SHAPE.wkt OUTDIR
// -> OUTDIR/packing.csv (the reference), packing.data, packing.vtp, packing.txt.
#include <exception>
#include <filesystem>
#include <iostream>

#include "frontpack/frontpack.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: frontpack_write_formats SHAPE.wkt OUTDIR\n";
    return 1;
  }
  try {
    const frontpack::Domain domain = frontpack::Domain::from_wkt_file(argv[1]);
    frontpack::FillOptions options;
    options.radii = frontpack::Radii::uniform(0.01, 0.05);
    options.seed = 11;
    const frontpack::Packing packing = frontpack::fill(domain, options);
    const std::filesystem::path dir = argv[2];
    std::filesystem::create_directories(dir);
    for (const char* name : {"packing.csv", "packing.data", "packing.vtp", "packing.txt"}) {
      const std::filesystem::path path = dir / name;
      frontpack::write_file(path, frontpack::format_from_path(path), domain, packing.disks);
    }
    std::cout << packing.disks.size() << " disks written to " << dir.string() << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "frontpack_write_formats: " << e.what() << "\n";
    return 2;
  }
}
