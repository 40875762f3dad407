// The frontpack command-line tool. It maps library errors to messages and exit codes; the
// library itself never prints.
//
// Exit codes: 0 success, 1 usage error, 2 unreadable input file, 3 WKT syntax or unsupported
// geometry, 4 invalid domain, 70 internal error.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <string>

#include "frontpack/frontpack.hpp"

namespace {

enum Exit : int { ok = 0, usage = 1, io = 2, wkt = 3, invalid_domain = 4, internal = 70 };

struct DomainSource {
  std::string file;
  std::string wkt;
};

void add_domain_options(CLI::App& cmd, DomainSource& src) {
  auto* file = cmd.add_option("DOMAIN", src.file, "WKT file with a POLYGON or MULTIPOLYGON");
  auto* text = cmd.add_option("--wkt", src.wkt, "the domain as WKT text instead of a file");
  file->excludes(text);
  text->excludes(file);
}

frontpack::Domain load(const DomainSource& src) {
  if (!src.wkt.empty()) {
    return frontpack::Domain::from_wkt(src.wkt);
  }
  if (src.file.empty()) {
    throw CLI::RequiredError("DOMAIN or --wkt");
  }
  return frontpack::Domain::from_wkt_file(src.file);
}

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

int run_info(const DomainSource& src) {
  const frontpack::Domain domain = load(src);
  const frontpack::Box b = domain.bbox();
  std::cout << "domain:     " << (src.wkt.empty() ? src.file : std::string("--wkt")) << "\n"
            << "polygons:   " << domain.num_polygons() << "\n"
            << "holes:      " << domain.num_holes() << "\n"
            << "vertices:   " << domain.num_vertices() << "\n"
            << "area:       " << fmt(domain.area()) << "\n"
            << "perimeter:  " << fmt(domain.perimeter()) << "\n"
            << "bbox:       [" << fmt(b.xmin) << ", " << fmt(b.xmax) << "] x [" << fmt(b.ymin) << ", " << fmt(b.ymax)
            << "]\n"
            << "valid:      yes (OGC simple features, decided exactly)\n";
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"frontpack: dense, exactly certified disk packings of polygonal domains", "frontpack"};
  app.set_version_flag("--version", std::string(frontpack::version_string));
  app.require_subcommand(1);

  DomainSource info_src;
  auto* info = app.add_subcommand("info", "Load and validate a domain, and print its summary");
  add_domain_options(*info, info_src);
  info->footer(
      "Example:\n"
      "  frontpack info shapes/concave_polygon.wkt\n"
      "  frontpack info --wkt 'POLYGON((0 0, 2 0, 2 1, 0 1, 0 0))'");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? ok : usage;
  }

  try {
    if (*info) {
      return run_info(info_src);
    }
    return usage;
  } catch (const CLI::ParseError& e) {
    std::cerr << "frontpack: " << e.what() << "\n";
    return usage;
  } catch (const frontpack::IoError& e) {
    std::cerr << "frontpack: " << e.what() << "\n";
    return io;
  } catch (const frontpack::WktError& e) {
    std::cerr << "frontpack: " << e.what() << "\n";
    return wkt;
  } catch (const frontpack::InvalidDomainError& e) {
    std::cerr << "frontpack: " << e.what() << "\n";
    return invalid_domain;
  } catch (const std::exception& e) {
    std::cerr << "frontpack: internal error: " << e.what() << "\n";
    return internal;
  }
}
