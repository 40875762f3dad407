#include "cli.hpp"

#include <exception>
#include <filesystem>
#include <limits>
#include <string_view>
#include <utility>

#include "domain_files.hpp"
#include "option_values.hpp"

namespace frontpack_tool::cli {

namespace {

SignalWatch* g_signals = nullptr;

}  // namespace

void set_signal_watch(SignalWatch* watch) {
  g_signals = watch;
}

std::stop_token stop_token() {
  return g_signals != nullptr ? g_signals->token() : std::stop_token{};
}

void add_domain_source_options(CLI::App& cmd, DomainSource& src) {
  src.wkt_option = cmd.add_option("--wkt", src.wkt, "the domain as WKT text instead of a DOMAIN file");
  cmd.add_option("--domain-format", src.format,
                 "format of DOMAIN instead of its extension: wkt, dxf, geojson, shapefile");
  cmd.add_option("--max-deviation", src.max_deviation,
                 "largest distance between a DXF curve and the polyline that replaces it, on the domain's side "
                 "(default: rmin/10 in fill, else 1e-3 of each curve's radius)");
  for (const frontpack::OptionInfo& info : frontpack::fill_option_list()) {
    if (info.budget) {
      cmd.add_option(frontpack::flag_name(info), src.budget_text[std::string(info.name)], option_help(info));
    }
  }
}

void add_domain_options(CLI::App& cmd, DomainSource& src) {
  auto* file = cmd.add_option("DOMAIN", src.file, kDomainFileHelp);
  add_domain_source_options(cmd, src);
  file->excludes(src.wkt_option);
  src.wkt_option->excludes(file);
}

void add_periodic_options(CLI::App& cmd, DomainSource& src) {
  src.periodic_option = cmd.add_option(
      "--periodic", src.periodic,
      "a periodic cell instead of a DOMAIN file: LX,LY (the cell [0,LX) x [0,LY)) or XMIN,YMIN,XMAX,YMAX");
  cmd.add_option("--periodic-axes", src.periodic_axes,
                 "with --periodic: xy (periodic in x and y) or x (periodic in x, walls at the bottom and top)")
      ->capture_default_str()
      ->needs(src.periodic_option);
  if (src.wkt_option != nullptr) {
    src.periodic_option->excludes(src.wkt_option);
    src.wkt_option->excludes(src.periodic_option);
  }
}

frontpack::Domain periodic_domain(const std::string& text, const std::string& axes) {
  frontpack::Periodicity periodicity = frontpack::Periodicity::none;
  if (axes == "xy") {
    periodicity = frontpack::Periodicity::xy;
  } else if (axes == "x") {
    periodicity = frontpack::Periodicity::x;
  } else {
    throw frontpack::OptionError(given_value("--periodic-axes", axes) + ": expected xy or x");
  }
  const std::string given = given_value("--periodic", text);
  const std::vector<double> values = finite_numbers("--periodic", text, "LX,LY or XMIN,YMIN,XMAX,YMAX");
  frontpack::Box cell;
  if (values.size() == 2) {
    cell = frontpack::Box{0, 0, values[0], values[1]};
  } else if (values.size() == 4) {
    cell = frontpack::Box{values[0], values[1], values[2], values[3]};
  } else {
    throw frontpack::OptionError(given + ": " + std::to_string(values.size()) +
                                 " numbers; expected LX,LY or XMIN,YMIN,XMAX,YMAX");
  }
  try {
    return frontpack::Domain::periodic(cell, periodicity);
  } catch (const frontpack::InvalidDomainError& e) {
    throw frontpack::OptionError(given + ": " + e.what());
  }
}

frontpack::Domain load(const DomainSource& src) {
  return load_file(src).domain;
}

frontpack::Budget budget(const DomainSource& src) {
  frontpack::FillOptions options;
  for (const auto& [name, text] : src.budget_text) {
    const frontpack::OptionInfo& info = frontpack::fill_option(name);
    if (!text.empty()) {
      frontpack::set_option(options, info, frontpack::parse_option(info, text, frontpack::flag_name(info)));
    }
  }
  return {.max_count = options.max_disks, .memory_limit = options.memory_limit};
}

frontpack::DomainFile load_file(const DomainSource& src, double default_deviation) {
  if (src.from_text()) {
    if (src.wkt.find_first_not_of(" \t\r\n") == std::string::npos) {
      throw frontpack::WktError(frontpack::WktError::Kind::empty_geometry,
                                "the WKT text given with --wkt is empty; expected a POLYGON or MULTIPOLYGON", 0, 1, 1,
                                "--wkt");
    }
    frontpack::Domain domain = frontpack::Domain::from_wkt(src.wkt);
    return {.domain = std::move(domain),
            .format = frontpack::DomainFormat::wkt,
            .contours = 0,
            .ignored_entities = 0,
            .curves = {},
            .units = {}};
  }
  if (src.from_periodic()) {
    return {.domain = periodic_domain(src.periodic, src.periodic_axes),
            .format = frontpack::DomainFormat::wkt,
            .contours = 0,
            .ignored_entities = 0,
            .curves = {},
            .units = {}};
  }
  if (src.file.empty()) {
    throw CLI::RequiredError("DOMAIN or --wkt");
  }
  return frontpack_tool::read_domain(src.file, src.format, src.max_deviation, default_deviation, budget(src));
}

std::vector<frontpack_tool::FileUse> domain_inputs(const DomainSource& src) {
  if (src.from_option() || src.file.empty()) {
    return {};
  }
  return {{"DOMAIN", src.file}};
}

std::vector<frontpack_tool::FileUse> output_uses(const std::vector<frontpack_tool::Output>& outputs,
                                                 const std::string& json) {
  std::vector<frontpack_tool::FileUse> uses;
  for (const auto& o : outputs) {
    uses.push_back({"-o", o.path});
  }
  if (!json.empty()) {
    uses.push_back({"--json", json});
  }
  return uses;
}

void refuse_empty_values(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_type_size() == 0) {
      continue;  // a flag
    }
    for (const std::string& value : option->results()) {
      if (value.empty()) {
        throw frontpack::OptionError(given_value(option->get_name(), value) + ": expected a value, got an empty one");
      }
    }
  }
}

std::string option_help(const frontpack::OptionInfo& info) {
  return std::string(info.help) + " (default " + frontpack::default_text(info) + ")";
}

int exit_code(const std::exception& e) {
  if (dynamic_cast<const frontpack_tool::UsageError*>(&e) != nullptr) {
    return usage;
  }
  if (dynamic_cast<const frontpack::IoError*>(&e) != nullptr ||
      dynamic_cast<const std::filesystem::filesystem_error*>(&e) != nullptr) {
    return io;
  }
  if (dynamic_cast<const frontpack::WktError*>(&e) != nullptr ||
      dynamic_cast<const frontpack::DomainFileError*>(&e) != nullptr) {
    return wkt;
  }
  if (dynamic_cast<const frontpack::InvalidDomainError*>(&e) != nullptr) {
    return invalid_domain;
  }
  if (dynamic_cast<const frontpack::DiskFileError*>(&e) != nullptr) {
    return bad_disk_file;
  }
  if (dynamic_cast<const frontpack::NothingFitsError*>(&e) != nullptr) {
    return nothing_fits;
  }
  if (dynamic_cast<const frontpack::OptionError*>(&e) != nullptr ||
      dynamic_cast<const frontpack::LimitError*>(&e) != nullptr) {
    return bad_option;
  }
  return internal;
}

void add_curve_input(const std::string& spec, std::vector<FileUse>& inputs) {
  constexpr std::string_view kCurve = "curve:";
  if (spec.compare(0, kCurve.size(), kCurve) == 0) {
    inputs.push_back({"--radius curve:FILE", spec.substr(kCurve.size())});
  }
}

}  // namespace frontpack_tool::cli
