// `frontpack stats`: packing statistics.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "frontpack/frontpack.hpp"
#include "option_values.hpp"
#include "outputs.hpp"
#include "packing_inputs.hpp"
#include "render.hpp"
#include "report.hpp"

namespace frontpack_tool::cli {

namespace {

struct StatsArgs {
  PackingInputs in;
  std::string radius;
  std::string json;
  std::string samples = "1000000";
  std::vector<std::string> hole_radii;
  std::string contact_gap;
  std::string cell_side;
  bool quiet = false;
};

int run_stats(StatsArgs& a) {
  resolve(a.in);
  frontpack::StatsOptions options;
  std::vector<frontpack_tool::FileUse> inputs = input_uses(a.in);
  if (!a.radius.empty()) {
    options.requested = frontpack::parse_radii(a.radius);
    add_curve_input(a.radius, inputs);
  }
  options.samples = parse_count("--samples", a.samples, std::uint64_t{1} << 40);
  for (const std::string& r : a.hole_radii) {
    options.hole_radii.push_back(parse_positive("--hole-radius", r));
  }
  if (!a.contact_gap.empty()) {
    options.contact_gap = parse_positive("--contact-gap", a.contact_gap);
  }
  if (!a.cell_side.empty()) {
    options.cell_side = parse_positive("--cell-side", a.cell_side);
  }
  options.budget = budget(a.in.domain);
  options.stop = stop_token();
  frontpack_tool::check_files(inputs, output_uses({}, a.json));
  const frontpack::Domain domain = load(a.in.domain);
  const std::vector<frontpack::Disk> disks = read_disks(a.in);
  const frontpack::PackingStats s = frontpack::measure(domain, disks, options);
  if (!a.json.empty()) {
    Json j{{"frontpack_version", frontpack::version_string},
           {"command", "stats"},
           {"domain", frontpack_tool::domain_json(a.in.domain.name(), domain)},
           {"disk_file", a.in.disks},
           {"disks", s.disks}};
    j.update(frontpack_tool::stats_json(s));
    frontpack_tool::PendingOutputs pending;
    pending.write_text(a.json, j.dump(2) + "\n");
    pending.commit_all(options.stop);
  }
  if (a.quiet) {
    return ok;
  }
  std::cout << "disks:        " << s.disks << " in " << a.in.disks << "\n"
            << "fraction:     " << frontpack_tool::fraction_line(s) << "\n"
            << "void ratio:   " << fmt(s.void_ratio) << "\n"
            << "radii:        " << frontpack_tool::radii_line(s.sizes) << "\n";
  if (s.sizes.compared) {
    std::cout << "requested:    " << s.sizes.requested << "\n"
              << "KS distance:  " << fmt4(s.sizes.ks_number) << " by number, " << fmt4(s.sizes.ks_area) << " by area\n";
  }
  std::cout << "coordination: " << fmt4(s.mean_coordination) << " mean, " << fmt4(s.interior_coordination)
            << " in the interior (" << s.interior_disks << " disks); " << s.contacts << " contacts, " << s.wall_contacts
            << " wall contacts, " << s.rattlers << " rattlers (gap <= " << fmt(s.contact_gap)
            << " counts as contact)\n";
  if (s.band_disks > 0 && s.band_disks < s.disks) {
    std::cout << "segregation:  median radius by area " << fmt(s.band_median_area) << " in the band (" << s.band_disks
              << " disks), " << fmt(s.inside_median_area) << " inside; KS by area " << fmt4(s.segregation_ks_area)
              << "\n";
  }
  for (const std::string& line : frontpack_tool::void_lines(s)) {
    std::cout << line << "\n";
  }
  return ok;
}

}  // namespace

Command add_stats(CLI::App& app) {
  auto args = std::make_shared<StatsArgs>();
  CLI::App* cmd = app.add_subcommand("stats", "Packing statistics: fractions, coordination, radii");
  add_packing_inputs(*cmd, args->in);
  cmd->add_option("--radius", args->radius, "compare the radii with this requested distribution");
  cmd->add_option("--samples", args->samples, "sample points for the interior and band fractions")
      ->capture_default_str();
  cmd->add_option("--hole-radius", args->hole_radii,
                  "count the holes that take a disk of this radius (repeatable; default: the median radius by number "
                  "and the largest)");
  cmd->add_option("--contact-gap", args->contact_gap,
                  "the largest gap between two disks, or a disk and a wall, that counts as a contact (default: 1e-9 "
                  "of the largest radius)");
  cmd->add_option("--cell-side", args->cell_side,
                  "the side of the square cells whose coverage is mapped (default: 8 times the largest radius)");
  cmd->add_option("--json", args->json, "write the statistics as JSON to this file");
  cmd->add_flag("-q,--quiet", args->quiet, "print nothing but errors");
  cmd->footer(
      "Example:\n"
      "  frontpack stats shapes/l_shape.wkt packing.csv --radius uniform:0.01,0.05 --json stats.json");
  return {cmd, [args] { return run_stats(*args); }};
}

}  // namespace frontpack_tool::cli
