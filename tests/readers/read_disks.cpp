// Reads a disk file with frontpack::read_disks (strict) and certifies it against a domain:
// frontpack_read_disks DISKS.csv|.txt SHAPE.wkt -> "N disks read, certified" (exit 0), or the
// error (exit 1). Used to check that the tool's files hold the certificate.
#include <exception>
#include <iostream>

#include "frontpack/frontpack.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: frontpack_read_disks DISKS SHAPE.wkt\n";
    return 1;
  }
  try {
    const auto disks = frontpack::read_disks(argv[1]);
    const auto report = frontpack::certify(frontpack::Domain::from_wkt_file(argv[2]), disks);
    if (!report.outside.empty() || !report.overlapping.empty()) {
      std::cerr << report.outside.size() << " disks outside, " << report.overlapping.size() << " overlapping pairs\n";
      return 1;
    }
    std::cout << disks.size() << " disks read, certified\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "frontpack_read_disks: " << e.what() << "\n";
    return 1;
  }
}
