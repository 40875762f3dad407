// The frontpack command-line tool. It maps library errors to messages and exit codes; the
// library itself never prints.
//
// Exit codes: 0 success, 1 usage error, 2 unreadable input or unwritable output file, 3 WKT
// syntax or unsupported geometry, 4 invalid domain, 5 invalid option (radius, method, limit),
// 70 internal error.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"

namespace {

enum Exit : int { ok = 0, usage = 1, io = 2, wkt = 3, invalid_domain = 4, bad_option = 5, internal = 70 };

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

// One exit code per kind of error (see the top of this file).
int exit_code(const std::exception& e) {
  if (dynamic_cast<const frontpack::IoError*>(&e) != nullptr ||
      dynamic_cast<const std::filesystem::filesystem_error*>(&e) != nullptr) {
    return io;
  }
  if (dynamic_cast<const frontpack::WktError*>(&e) != nullptr) {
    return wkt;
  }
  if (dynamic_cast<const frontpack::InvalidDomainError*>(&e) != nullptr) {
    return invalid_domain;
  }
  if (dynamic_cast<const frontpack::OptionError*>(&e) != nullptr ||
      dynamic_cast<const frontpack::LimitError*>(&e) != nullptr) {
    return bad_option;
  }
  return internal;
}

// "uniform:RMIN,RMAX" or "constant:R".
frontpack::Radii parse_radius(const std::string& spec) {
  const auto colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  const std::string args = colon == std::string::npos ? std::string() : spec.substr(colon + 1);
  const auto number = [&](const std::string& text) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size()) {
      throw frontpack::OptionError("--radius " + spec + ": '" + text + "' is not a number");
    }
    return v;
  };
  if (kind == "constant" && !args.empty()) {
    return frontpack::Radii::constant(number(args));
  }
  if (kind == "uniform") {
    const auto comma = args.find(',');
    if (comma != std::string::npos) {
      return frontpack::Radii::uniform(number(args.substr(0, comma)), number(args.substr(comma + 1)));
    }
  }
  throw frontpack::OptionError("--radius " + spec + ": expected uniform:RMIN,RMAX or constant:R");
}

struct FillArgs {
  DomainSource src;
  std::string method = "closed";
  std::string radius = "uniform:0.01,0.05";
  std::uint64_t seed = 0;
  std::vector<std::string> outputs;
};

// Writes to a temporary file beside the target and renames it, so that a failure never leaves
// a partial file behind.
void write_output(const std::string& path, const frontpack::Domain& domain, const frontpack::Packing& packing) {
  const std::filesystem::path target(path);
  const std::string ext = target.extension().string();
  if (ext != ".csv" && ext != ".svg") {
    throw frontpack::OptionError("-o " + path + ": unknown format '" + ext + "' (this version writes .csv and .svg)");
  }
  const std::filesystem::path tmp = target.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) {
      throw frontpack::IoError("cannot write '" + tmp.string() + "'", tmp.string());
    }
    if (ext == ".csv") {
      frontpack::write_csv(out, packing.disks);
    } else {
      frontpack::write_svg(out, domain, packing.disks);
    }
    if (!out.flush()) {
      throw frontpack::IoError("cannot write '" + tmp.string() + "'", tmp.string());
    }
  }
  std::filesystem::rename(tmp, target);
}

int run_fill(const FillArgs& a) {
  const frontpack::Domain domain = load(a.src);
  frontpack::FillOptions options;
  if (a.method == "closed") {
    options.method = frontpack::Method::closed;
  } else if (a.method == "open") {
    options.method = frontpack::Method::open;
  } else {
    throw frontpack::OptionError("--method " + a.method + ": expected closed or open");
  }
  options.radii = parse_radius(a.radius);
  options.seed = a.seed;
  const frontpack::Packing p = frontpack::fill(domain, options);
  for (const std::string& path : a.outputs) {
    write_output(path, domain, p);
  }
  double area = 0;
  for (const frontpack::Disk& d : p.disks) {
    area += std::numbers::pi * d.radius * d.radius;
  }
  const frontpack::Certificate& c = p.certificate;
  std::cerr << "disks:       " << p.disks.size() << " (" << frontpack::to_string(options.method) << " form, seed "
            << a.seed << ")\n"
            << "fraction:    " << fmt(area / domain.area()) << " of the domain's area\n"
            << "certificate: " << (c.dropped == 0 ? "certified" : "repaired") << ": " << c.generated << " generated, "
            << c.culled << " culled (not inside), " << c.dropped << " dropped (overlap); every decision exact\n"
            << "time:        " << fmt(p.stats.seconds_front + p.stats.seconds_cull + p.stats.seconds_overlap)
            << " s (front " << fmt(p.stats.seconds_front) << ", cull " << fmt(p.stats.seconds_cull) << ", overlap pass "
            << fmt(p.stats.seconds_overlap) << ")\n";
  for (const std::string& path : a.outputs) {
    std::cerr << "wrote:       " << path << "\n";
  }
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

  FillArgs fill_args;
  auto* fill = app.add_subcommand("fill", "Fill a domain with disks (advancing front, certified exactly)");
  add_domain_options(*fill, fill_args.src);
  fill->add_option("--method", fill_args.method, "closed (Sec. 2) or open (Sec. 3)")->capture_default_str();
  fill->add_option("--radius", fill_args.radius, "uniform:RMIN,RMAX or constant:R")->capture_default_str();
  fill->add_option("--seed", fill_args.seed, "64-bit seed (same seed, same packing)")->capture_default_str();
  fill->add_option("-o,--output", fill_args.outputs, "output file(s): .csv (x,y,r) or .svg (picture)");
  fill->footer(
      "Example:\n"
      "  frontpack fill shapes/concave_polygon.wkt --radius uniform:0.005,0.02 -o packing.csv -o packing.svg");

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
    if (*fill) {
      return run_fill(fill_args);
    }
    return usage;
  } catch (const CLI::ParseError& e) {
    std::cerr << "frontpack: " << e.what() << "\n";
    return usage;
  } catch (const std::exception& e) {
    const int code = exit_code(e);
    std::cerr << "frontpack: " << (code == internal ? "internal error: " : "") << e.what() << "\n";
    return code;
  }
}
