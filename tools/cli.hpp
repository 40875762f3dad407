// The command-line tool's shared parts: exit codes, the signal watch's stop token, the domain
// given as a file or as --wkt, and one function per subcommand
// (tools/commands/) that registers it and returns how to run it.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <stop_token>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "outputs.hpp"
#include "signals.hpp"

namespace frontpack_tool::cli {

enum Exit : int {
  ok = 0,
  usage = 1,
  io = 2,
  wkt = 3,
  invalid_domain = 4,
  bad_option = 5,
  not_certified = 6,
  bad_disk_file = 7,
  nothing_fits = 8,
  max_disks_reached = 9,
  internal = 70,
};

constexpr const char* kExitCodes =
    "Exit codes: 0 success, 1 usage error, 2 unreadable input or unwritable output, 3 WKT syntax,\n"
    "unsupported geometry or entity, open contour (DXF, GeoJSON, Shapefile), 4 invalid domain, 5\n"
    "invalid option (radius, method, format, width, seed, limit, deviation), 6 packing not certified\n"
    "(check), 7 malformed disk file, 8 no disk fits (fill), 9 stopped at --max-disks (fill; the\n"
    "partial packing is written), 70 internal error, 130/143/129 stopped by SIGINT/SIGTERM/SIGHUP.\n"
    "Outputs are written to temporary files and renamed together at the end: a failed or interrupted\n"
    "run leaves every file as it was. /dev/stdout, devices and FIFOs are written through.";

constexpr const char* kRadiusHelp =
    "radius distribution: uniform:RMIN,RMAX | constant:R | normal:MEAN,SD[,LO,HI] | "
    "lognormal:MEDIAN,GSD[,LO,HI] | discrete:S1:F1,S2:F2,...[@area] | curve:FILE.csv (sizes.hpp)";

/// The process's signal watch (set once in main, before any other thread), and its stop token
/// (none before it is set).
void set_signal_watch(SignalWatch* watch);
[[nodiscard]] std::stop_token stop_token();

struct DomainSource {
  std::string file;
  std::string wkt;
  std::string format;                // --domain-format: "" (by extension), wkt, dxf, geojson, shapefile
  std::string max_deviation;         // --max-deviation: "" for the command's default
  std::string periodic;              // --periodic LX,LY | XMIN,YMIN,XMAX,YMAX
  std::string periodic_axes = "xy";  // --periodic-axes xy | x
  // --max-disks, --memory-limit: the Budget (frontpack/budget.hpp) every count is held to; the
  // text given for each fill option that is also the Budget (OptionInfo::budget), by name ("" if
  // not given: the description's default)
  std::map<std::string, std::string, std::less<>> budget_text;
  CLI::Option* wkt_option = nullptr;
  CLI::Option* periodic_option = nullptr;
  [[nodiscard]] bool from_text() const { return wkt_option != nullptr && wkt_option->count() > 0; }
  [[nodiscard]] bool from_periodic() const { return periodic_option != nullptr && periodic_option->count() > 0; }
  /// Whether the domain comes from an option (--wkt, --periodic) rather than a DOMAIN file.
  [[nodiscard]] bool from_option() const { return from_text() || from_periodic(); }
  [[nodiscard]] std::string name() const {
    return from_text() ? std::string("--wkt") : from_periodic() ? "--periodic " + periodic : file;
  }
};

constexpr const char* kDomainFileHelp =
    "domain file: WKT (POLYGON or MULTIPOLYGON), DXF (closed polylines with bulges, CIRCLE, LINE+ARC), GeoJSON or "
    "Shapefile (polygons), by extension";

/// DOMAIN (a file: WKT, DXF, GeoJSON, Shapefile) or --wkt TEXT, each excluding the other, and
/// --domain-format, --max-deviation, --max-disks, --memory-limit.
void add_domain_options(CLI::App& cmd, DomainSource& src);
/// The same without the DOMAIN positional (for commands that take more positionals).
void add_domain_source_options(CLI::App& cmd, DomainSource& src);
/// --periodic and --periodic-axes (excluding --wkt when that is registered first): the domain is a
/// periodic cell, periodic_domain(src.periodic, src.periodic_axes).
void add_periodic_options(CLI::App& cmd, DomainSource& src);

/// The periodic cell of `--periodic TEXT --periodic-axes AXES`: TEXT is "LX,LY" (the cell
/// [0, LX) x [0, LY)) or "XMIN,YMIN,XMAX,YMAX"; numbers as std::from_chars reads them, finite;
/// AXES is "xy" (a torus) or "x" (periodic in x, walls at the bottom and top). Throws OptionError
/// naming the option and the value (an empty cell included).
[[nodiscard]] frontpack::Domain periodic_domain(const std::string& text, const std::string& axes);

/// The domain given; throws as Domain::from_wkt or read_domain_file, or CLI::RequiredError if
/// none is. Curves get --max-deviation, else `default_deviation` (0: the library's relative one).
[[nodiscard]] frontpack::DomainFile load_file(const DomainSource& src, double default_deviation = 0);
[[nodiscard]] frontpack::Domain load(const DomainSource& src);
/// The Budget of --max-disks and --memory-limit (OptionError naming the option and the value).
[[nodiscard]] frontpack::Budget budget(const DomainSource& src);
/// The domain file as an input that no output may overwrite (none for --wkt).
[[nodiscard]] std::vector<FileUse> domain_inputs(const DomainSource& src);
/// The outputs and the --json file as outputs for check_files().
[[nodiscard]] std::vector<FileUse> output_uses(const std::vector<Output>& outputs, const std::string& json);

/// The file a `curve:FILE` radius spec reads, as an input that no output may overwrite.
void add_curve_input(const std::string& spec, std::vector<FileUse>& inputs);

/// Refuses (OptionError) an option or argument of `command` given an empty value: '--clearance ""'
/// would otherwise read as an option not given. Flags take no value and are not checked.
void refuse_empty_values(const CLI::App& command);

/// A fill option's help: its description's sentence and default (frontpack/options.hpp).
[[nodiscard]] std::string option_help(const frontpack::OptionInfo& info);

/// One exit code per kind of error (see the top of tools/frontpack.cpp).
[[nodiscard]] int exit_code(const std::exception& e);

/// A subcommand: its CLI11 app, and what runs it once the command line is parsed.
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

Command add_info(CLI::App& app);
Command add_fill(CLI::App& app);
Command add_check(CLI::App& app);
Command add_render(CLI::App& app);
Command add_stats(CLI::App& app);

}  // namespace frontpack_tool::cli
