// The README's library example, compiled against the installed package by the test suite.
#include <frontpack/frontpack.hpp>
#include <iostream>

int main(int argc, char** argv) try {
  const auto domain = frontpack::Domain::from_wkt_file(argc > 1 ? argv[1] : "shapes/concave_polygon.wkt");
  const frontpack::Disk disk{{0.25, 0.25}, 0.1};
  std::cout << "area " << domain.area() << ", disk inside: " << domain.contains(disk)
            << ", (0 0) is " << frontpack::to_string(domain.locate({0, 0})) << "\n";
} catch (const frontpack::Error& e) {
  std::cerr << e.what() << "\n";
  return 1;
}
