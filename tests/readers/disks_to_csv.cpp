// Reads a disk file in any format frontpack reads (frontpack::read_disks, by its extension) and
// writes the disks as CSV (write_csv), so that a test compares them with a reference bit for bit:
// frontpack_disks_to_csv DISKS OUT.csv -> "N disks" (exit 0), or the error (exit 1).
#include <exception>
#include <iostream>

#include "frontpack/frontpack.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: frontpack_disks_to_csv DISKS OUT.csv\n";
    return 1;
  }
  try {
    const auto disks = frontpack::read_disks(argv[1]);
    frontpack::write_file(argv[2], frontpack::Format::csv, frontpack::Domain::from_wkt("POLYGON((0 0,1 0,1 1,0 0))"),
                          disks);
    std::cout << disks.size() << " disks\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "frontpack_disks_to_csv: " << e.what() << "\n";
    return 1;
  }
}
