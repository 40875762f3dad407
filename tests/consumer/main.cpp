// The README's library example, compiled against the installed package by the test suite.
#include <frontpack/frontpack.hpp>
#include <iostream>

int main(int argc, char** argv) try {
  const auto domain = frontpack::Domain::from_wkt_file(argc > 1 ? argv[1] : "shapes/concave_polygon.wkt");
  frontpack::FillOptions options;
  options.radii = frontpack::Radii::uniform(0.005, 0.02);
  const frontpack::Packing packing = frontpack::fill(domain, options);
  std::cout << packing.disks.size() << " disks, area " << domain.area() << ", " << packing.certificate.dropped
            << " overlaps\n";
} catch (const frontpack::Error& e) {
  std::cerr << e.what() << "\n";
  return 1;
}
