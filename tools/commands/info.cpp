// `frontpack info`: load and validate a domain, print its summary.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "cli.hpp"
#include "domain_files.hpp"
#include "frontpack/frontpack.hpp"
#include "outputs.hpp"
#include "render.hpp"
#include "report.hpp"

namespace frontpack_tool::cli {

namespace {

int run_info(const DomainSource& src) {
  const frontpack::DomainFile file = load_file(src);
  const frontpack::Domain& domain = file.domain;
  const frontpack::Box b = domain.bbox();
  std::cout << "domain:     " << src.name() << "\n"
            << "polygons:   " << domain.num_polygons() << "\n"
            << "holes:      " << domain.num_holes() << "\n"
            << "vertices:   " << domain.num_vertices() << "\n"
            << "area:       " << fmt(domain.area()) << "\n"
            << "perimeter:  " << fmt(domain.perimeter()) << "\n"
            << "bbox:       [" << fmt(b.xmin) << ", " << fmt(b.xmax) << "] x [" << fmt(b.ymin) << ", " << fmt(b.ymax)
            << "]\n"
            << "valid:      yes (OGC simple features, decided exactly)\n"
            << (file.ignored_entities > 0 ? "ignored:    " + std::to_string(file.ignored_entities) +
                                                " annotation entities (text, dimensions, hatches, points)\n"
                                          : std::string())
            << units_line(file) << curve_lines(file, 50);
  return ok;
}

}  // namespace

Command add_info(CLI::App& app) {
  auto args = std::make_shared<DomainSource>();
  CLI::App* cmd = app.add_subcommand("info", "Load and validate a domain, and print its summary");
  add_domain_options(*cmd, *args);
  cmd->footer(
      "Example:\n"
      "  frontpack info shapes/concave_polygon.wkt\n"
      "  frontpack info --wkt 'POLYGON((0 0, 2 0, 2 1, 0 1, 0 0))'\n"
      "  frontpack info drum.dxf --max-deviation 0.001   (curves: the segments each became)");
  return {cmd, [args] { return run_info(*args); }};
}

}  // namespace frontpack_tool::cli
