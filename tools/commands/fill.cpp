// `frontpack fill`: fill a domain, write the packing, print the summary.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "domain_files.hpp"
#include "frontpack/frontpack.hpp"
#include "option_values.hpp"
#include "outputs.hpp"
#include "progress.hpp"
#include "render.hpp"
#include "report.hpp"

namespace frontpack_tool::cli {

namespace {

constexpr const char* kDefaultRadius = frontpack::default_radius_spec;

struct FillArgs {
  DomainSource src;
  std::string method = frontpack::to_string(frontpack::FillOptions{}.method);
  std::string radius;  // empty: kDefaultRadius
  std::string seed = "0";
  std::vector<std::string> outputs;
  std::string format;
  std::string json;
  std::string window;
  std::string start;
  std::string clearance;
  int width = 1200;
  bool no_voids = false;
  bool jam = false;
  bool no_histogram = false;
  bool holes = false;
  bool quiet = false;
  bool progress = false;
  std::string types;                // --types RULE
  std::vector<std::string> deck{};  // --deck SIMULATOR DIR
  std::string density;              // --density SPEC
  std::string thickness;            // --thickness T
  std::string wall_radius;          // --wall-radius W
  std::string fraction;             // --fraction F
  std::string count;                // --count N
  std::string height;               // --height H
};

// --start X,Y: the closed form's first disks (FillOptions::start).
frontpack::Point parse_point(const char* option, const std::string& text) {
  static constexpr const char* kExpected = "two numbers X,Y, e.g. 0.5,0.25";
  const std::vector<double> xy = finite_numbers(option, text, kExpected);
  if (xy.size() != 2) {
    throw frontpack::OptionError(given_value(option, text) + ": expected " + kExpected);
  }
  return {xy[0], xy[1]};
}

// The library options that have flags, beyond method, radius, seed and limits.
void apply_front_options(const FillArgs& a, frontpack::FillOptions& options) {
  if (!a.window.empty()) {
    options.window = parse_count("--window", a.window, std::uint64_t{1} << 32);
  }
  if (!a.start.empty()) {
    if (options.method != frontpack::Method::closed) {
      throw frontpack::OptionError("--start is where the closed form (--method closed) places its first disks; the " +
                                   std::string(frontpack::to_string(options.method)) + " form has no start point");
    }
    options.start = parse_point("--start", a.start);
  }
  if (!a.clearance.empty()) {
    options.clearance = parse_double("--clearance", a.clearance);
    if (!(options.clearance > 0)) {
      throw frontpack::OptionError(given_value("--clearance", a.clearance) +
                                   ": expected a gap > 0 between tangent disks (leave it out for the automatic one)");
    }
  }
  options.fill_voids = !a.no_voids;
  options.jam = a.jam;
  if (!a.fraction.empty()) {
    options.fraction = parse_double("--fraction", a.fraction);
  }
  if (!a.count.empty()) {
    options.count = parse_count("--count", a.count, std::numeric_limits<std::uint64_t>::max(), 1);
  }
  if (!a.height.empty()) {
    options.height = parse_double("--height", a.height);
  }
}

// The deck's options, checked before any work; the directory is created if missing (and removed
// again if the run writes nothing: make_output_directory).
struct DeckPlan {
  bool wanted = false;
  frontpack::DeckOptions options;
  std::filesystem::path dir;
};

DeckPlan plan_deck(const FillArgs& a, std::uint32_t types) {
  DeckPlan plan;
  if (a.deck.empty()) {
    for (const auto& [name, value] : {std::pair{"--density", &a.density}, std::pair{"--thickness", &a.thickness},
                                      std::pair{"--wall-radius", &a.wall_radius}}) {
      if (!value->empty()) {
        throw frontpack::OptionError(std::string(name) + " sets up a simulator deck: it needs --deck SIMULATOR DIR");
      }
    }
    return plan;
  }
  plan.wanted = true;
  plan.options.simulator = frontpack::simulator_from_name(a.deck[0]);
  plan.dir = a.deck[1];
  if (a.density.empty()) {
    throw frontpack::OptionError(
        "--deck needs --density: one density for all types (e.g. 2500) or one per type "
        "(1:2500,2:7800); mass per area, or per volume with --thickness");
  }
  plan.options.densities = frontpack::parse_densities(a.density, types);
  plan.options.thickness = a.thickness.empty() ? 0.0 : parse_positive("--thickness", a.thickness);
  plan.options.wall_radius = a.wall_radius.empty() ? 0.0 : parse_positive("--wall-radius", a.wall_radius);
  if (plan.options.simulator != frontpack::Simulator::lammps && !a.wall_radius.empty()) {
    throw frontpack::OptionError("--wall-radius sets the LAMMPS deck's wall disks; the " +
                                 std::string(frontpack::to_string(plan.options.simulator)) + " deck has mesh walls");
  }
  return plan;
}

frontpack::Method parse_method(const std::string& name) {
  if (name == "closed") {
    return frontpack::Method::closed;
  }
  if (name == "open") {
    return frontpack::Method::open;
  }
  if (name == "boundary") {
    return frontpack::Method::boundary;
  }
  throw frontpack::OptionError(given_value("--method", name) + ": expected closed, open or boundary");
}

Json fill_json(const FillArgs& a, const std::string& spec, const frontpack::FillOptions& options,
               const frontpack::Domain& domain, const frontpack::Packing& p, const frontpack::PackingStats& s,
               const std::vector<frontpack_tool::Output>& outputs, double seconds_stats, double seconds_total) {
  Json outs = Json::array();
  for (const auto& o : outputs) {
    outs.push_back(Json{{"path", o.path.string()}, {"format", frontpack_tool::format_name(o.format)}});
  }
  Json j{{"frontpack_version", frontpack::version_string},
         {"command", "fill"},
         {"domain", frontpack_tool::domain_json(a.src.name(), domain)},
         {"method", frontpack::to_string(options.method)},
         {"radius_spec", spec},
         {"radius_spec_given", !a.radius.empty()},
         {"radius_distribution", options.radii.describe()},
         {"seed", options.seed},
         {"disks", p.disks.size()},
         {"truncated", p.truncated}};
  j.update(frontpack_tool::stats_json(s));
  j["certificate"] = frontpack_tool::certificate_json(p.certificate);
  Json stats = frontpack_tool::fill_stats_json(p.stats, options.jam);
  for (auto& group : stats.items()) {
    j[group.key()] = std::move(group.value());
  }
  j["seconds"]["statistics"] = seconds_stats;
  j["seconds"]["total"] = seconds_total;
  if (p.target) {
    j["target"] = frontpack_tool::target_json(*p.target);
  }
  j["outputs"] = outs;
  return j;
}

// Sample points of the interior and band fractions: 1M in the JSON summary (as `frontpack
// stats`: +/- 0.0005), a quarter of that in the text summary (+/- 0.001, printed with it), which at
// a million disks then costs a tenth of the fill or a little more (docs/performance.md, "The summary").
struct StatsSamples {
  static constexpr std::size_t json = 1'000'000;
  static constexpr std::size_t text = 250'000;
};

int run_fill(const FillArgs& a) {
  const auto t_start = Clock::now();
  const std::string spec = a.radius.empty() ? std::string(kDefaultRadius) : a.radius;
  frontpack::FillOptions options;
  options.method = parse_method(a.method);
  options.radii = frontpack::parse_radii(spec);
  options.seed = parse_count("--seed", a.seed, std::numeric_limits<std::uint64_t>::max());
  const frontpack::Budget limits = budget(a.src);
  options.max_disks = limits.max_count;
  options.memory_limit = limits.memory_limit;
  options.stop = stop_token();
  apply_front_options(a, options);
  const std::vector<frontpack_tool::Output> outputs = frontpack_tool::resolve_outputs(a.outputs, a.format, false);
  const frontpack::TypeRule type_rule = a.types.empty() ? frontpack::TypeRule{} : frontpack::parse_type_rule(a.types);
  DeckPlan deck = plan_deck(a, type_rule.count());
  deck.options.stop = options.stop;
  deck.options.budget = limits;
  std::vector<frontpack_tool::FileUse> inputs = domain_inputs(a.src);
  add_curve_input(spec, inputs);
  for (const std::string& region : type_rule.region_names) {
    inputs.push_back({"--types region:FILE", region});
  }
  std::vector<frontpack_tool::FileUse> output_files = output_uses(outputs, a.json);
  if (deck.wanted) {
    if (std::filesystem::exists(deck.dir) && !std::filesystem::is_directory(deck.dir)) {
      throw frontpack::IoError("--deck directory '" + deck.dir.string() + "' is not a directory", deck.dir.string());
    }
    frontpack_tool::make_output_directory(deck.dir);
    for (const std::string& name : frontpack::deck_file_names(deck.options.simulator)) {
      output_files.push_back({"--deck", deck.dir / name});
    }
  }
  frontpack_tool::check_files(inputs, output_files);
  // Curves become polylines within a tenth of the smallest radius of the domain's true boundary.
  const frontpack::DomainFile file = load_file(a.src, options.radii.min() / 10);
  const frontpack::Domain& domain = file.domain;
  if (options.start && domain.num_polygons() > 1) {
    throw frontpack::OptionError("--start: the domain has " + std::to_string(domain.num_polygons()) +
                                 " polygons, each filled from its own start (the centre of its bounding box); "
                                 "--start takes a domain of one polygon");
  }

  frontpack_tool::ProgressLine line(frontpack_tool::ProgressLine::mode_for(!a.quiet, a.progress));
  frontpack::Packing p;
  {
    frontpack::Generator generator(domain, options);
    generator.on_progress([&line](const frontpack::Progress& progress) {
      line.update(progress);
      return true;
    });
    try {
      p = generator.run();
    } catch (const frontpack::NothingFitsError& e) {
      line.clear();
      std::cerr << "frontpack: " << e.what() << "; nothing written\n";
      return nothing_fits;
    }
  }

  // Statistics only where they are shown or written: the text summary shows the fractions and
  // the radii only; the JSON summary has the contacts and the quality measures too (empty circle,
  // coverage profile and cells: about 0.6 s per million disks), and the hole counts (about 3 s
  // more) only with --holes (`frontpack stats` shows them).
  const auto t_stats = Clock::now();
  frontpack::PackingStats s;
  if (!a.quiet || !a.json.empty()) {
    line.phase("measuring " + std::to_string(p.disks.size()) + " disks");
    const bool quality = !a.json.empty();
    s = frontpack::measure(domain, p.disks,
                           {.requested = quality ? std::optional<frontpack::Radii>(options.radii) : std::nullopt,
                            .samples = quality ? StatsSamples::json : StatsSamples::text,
                            .histogram_bins = quality ? frontpack::StatsOptions{}.histogram_bins : 0,
                            .contacts = quality,
                            .empty_circle = quality,
                            .holes = quality && a.holes,
                            .coverage_profile = quality,
                            .cell_coverage = quality,
                            .budget = limits,
                            .stop = options.stop});
  }
  const double seconds_stats = seconds_since(t_stats);

  frontpack_tool::PendingOutputs pending;
  const frontpack_tool::RenderOptions picture{.width_px = a.width,
                                              .histogram = !a.no_histogram,
                                              .requested = options.radii,
                                              .requested_spec = spec,
                                              .stop = options.stop};
  const std::vector<std::uint32_t> types =
      a.types.empty() ? std::vector<std::uint32_t>{} : frontpack::assign_types(type_rule, p.disks);
  for (const auto& o : outputs) {
    line.phase("writing " + o.path.string());
    pending.write(o, domain, p.disks, picture, options.stop, types);
  }
  std::vector<std::string> deck_files;
  if (deck.wanted) {
    line.phase("writing the " + std::string(frontpack::to_string(deck.options.simulator)) + " deck in " +
               deck.dir.string());
    for (const frontpack::DeckFile& f : frontpack::make_deck(domain, p.disks, types, deck.options)) {
      deck_files.push_back((deck.dir / f.name).string());
      pending.write_text(deck.dir / f.name, f.text);
    }
  }
  // Disks per type: [k] for type k + 1.
  std::vector<std::size_t> per_type;
  for (const std::uint32_t t : types) {
    per_type.resize(std::max<std::size_t>(per_type.size(), t), 0);
    ++per_type[t - 1];
  }
  if (!a.json.empty()) {
    Json j = fill_json(a, spec, options, domain, p, s, outputs, seconds_stats, seconds_since(t_start));
    if (!file.curves.empty()) {
      j["domain"]["curves"] = curves_json(file);
    }
    if (file.format == frontpack::DomainFormat::dxf) {
      j["domain"]["units"] = file.units;  // "" when the file states none
    }
    if (!types.empty()) {
      j["types"] = Json{{"rule", a.types}, {"disks_per_type", per_type}};
    }
    if (deck.wanted) {
      j["deck"] = Json{{"simulator", a.deck[0]}, {"directory", deck.dir.string()}, {"files", deck_files}};
    }
    pending.write_text(a.json, j.dump(2) + "\n");
  }
  line.phase("committing the outputs");
  pending.commit_all(options.stop);
  line.clear();

  if (!a.quiet) {
    const frontpack::Certificate& c = p.certificate;
    const double seconds_fill =
        p.stats.seconds_front + p.stats.seconds_jam + p.stats.seconds_cull + p.stats.seconds_overlap;
    std::cerr << "disks:       " << p.disks.size() << " (" << frontpack::to_string(options.method) << " form, seed "
              << options.seed << (p.truncated ? ", truncated at --max-disks" : "") << ")\n"
              << "radius:      " << spec << (a.radius.empty() ? " (the default; set with --radius)" : "") << "\n"
              << "fraction:    " << frontpack_tool::fraction_line(s) << "\n"
              << "radii:       " << frontpack_tool::radii_line(s.sizes) << "\n"
              << (p.target ? "target:      " + frontpack_tool::target_line(*p.target) + "\n" : std::string())
              << "certificate: " << (c.dropped == 0 ? "certified" : "certified after repair") << ": " << c.generated
              << " generated, " << c.culled << " culled (not inside), " << c.dropped
              << " dropped (overlap); every decision exact\n"
              << (options.jam ? "jam:         " + std::to_string(p.stats.jam_inserted) + " disks inserted in " +
                                    std::to_string(p.stats.jam_rounds) + " rounds, " +
                                    std::to_string(p.stats.jam_steps) + " relaxation steps\n"
                              : std::string())
              << "time:        " << fmt(seconds_fill) << " s (front " << fmt(p.stats.seconds_front)
              << (options.jam ? ", jam " + fmt(p.stats.seconds_jam) : std::string()) << ", cull "
              << fmt(p.stats.seconds_cull) << ", overlap pass " << fmt(p.stats.seconds_overlap) << "), statistics "
              << fmt(seconds_stats) << " s\n"
              << units_line(file) << curve_lines(file, 10);
    if (!types.empty()) {
      std::cerr << "types:       " << per_type.size() << " (" << a.types << "):";
      for (std::size_t k = 0; k < per_type.size(); ++k) {
        std::cerr << (k == 0 ? " " : ", ") << per_type[k] << " of type " << k + 1;
      }
      std::cerr << "\n";
    }
    for (const auto& o : outputs) {
      std::cerr << "wrote:       " << o.path.string() << " (" << frontpack_tool::format_name(o.format) << ")\n";
    }
    if (!a.json.empty()) {
      std::cerr << "wrote:       " << a.json << " (summary)\n";
    }
    for (const std::string& f : deck_files) {
      std::cerr << "wrote:       " << f << " (" << a.deck[0] << " deck)\n";
    }
  }
  if (p.truncated) {
    std::cerr << "frontpack: stopped at --max-disks " << options.max_disks << ": the packing written ("
              << p.disks.size() << (p.disks.size() == 1 ? " disk" : " disks")
              << ", certified) does not fill the domain\n";
    return max_disks_reached;
  }
  return ok;
}

}  // namespace

Command add_fill(CLI::App& app) {
  auto args = std::make_shared<FillArgs>();
  CLI::App* cmd = app.add_subcommand("fill", "Fill a domain with disks (advancing front, certified exactly)");
  add_domain_options(*cmd, args->src);
  add_periodic_options(*cmd, args->src);
  cmd->get_option("DOMAIN")->excludes(args->src.periodic_option);
  args->src.periodic_option->excludes(cmd->get_option("DOMAIN"));
  cmd->add_option("--method", args->method, "closed (Sec. 2), open (Sec. 3) or boundary (the domain's edges as walls)")
      ->capture_default_str();
  cmd->add_option("--radius", args->radius, std::string(kRadiusHelp) + " (default " + kDefaultRadius + ")");
  cmd->add_option("--seed", args->seed, "64-bit seed, 0 to 18446744073709551615 (same seed, same packing)")
      ->capture_default_str();
  cmd->add_option("-o,--output", args->outputs,
                  "output file, any number; format by extension: .csv, .txt/.yade (Yade), .data/.lmp (LAMMPS), "
                  ".vtp (ParaView), .png/.svg/.pdf (picture)");
  cmd->add_option("--format", args->format,
                  "format of every -o instead of the extension: csv, yade, lammps, "
                  "vtp, png, svg, pdf");
  cmd->add_option("--json", args->json, "write the summary as JSON to this file");
  cmd->add_option("--types", args->types,
                  "per-disk types (1-based) for every output: size:E1,E2,... (radius bin edges: r < E1 is type 1, "
                  "E1 <= r < E2 type 2, ...) or region:A.wkt,B.wkt,... (a centre in the closed region k is type "
                  "k+1, the first region wins; else 1)");
  cmd->add_option("--deck", args->deck,
                  "SIMULATOR DIR: write a deck that runs as it is into DIR (created if missing): lammps, liggghts or "
                  "yade (docs/simulators.md)")
      ->expected(2);
  cmd->add_option("--density", args->density,
                  "with --deck: density of every type (2500) or per type (1:2500,2:7800); mass per area, or per "
                  "volume with --thickness");
  cmd->add_option("--thickness", args->thickness,
                  "with --deck: the disks are cylinders this thick and --density is per volume");
  cmd->add_option("--wall-radius", args->wall_radius,
                  "with --deck lammps: radius of the frozen wall disks (default: the smallest radius)");
  cmd->add_option("--width", args->width, "picture width in pixels")->capture_default_str();
  cmd->add_flag("--no-histogram", args->no_histogram,
                "pictures without the size-distribution panel (histogram by area, KS distance)");
  cmd->add_flag("--holes", args->holes,
                "with --json: also count the holes that take the median and the largest radius (about 3 s "
                "per million disks; frontpack stats counts them always)");
  cmd->add_option("--window", args->window,
                  "front check window M of the paper's forms (Sec. 2.4.3): front disks examined on each side; 0: "
                  "the whole front (default 5)");
  cmd->add_option("--start", args->start,
                  "X,Y: where the closed form places its first three disks (default: the "
                  "centre of each polygon's bounding box)");
  cmd->add_option("--clearance", args->clearance,
                  "gap between tangent disks, at least 16 ulps of the coordinates (default: automatic, a few ulps; "
                  "docs/robustness.md)");
  cmd->add_flag("--no-voids", args->no_voids,
                "the paper's forms as published: no void filling (refused by --method boundary)");
  cmd->add_flag("--jam", args->jam,
                "after the front, insert disks and relax the overlaps away until the packing jams: denser (bidisperse "
                "1:1.4: about 0.837 instead of 0.815; little change at wide size ranges); costs minutes per "
                "100,000 disks (docs/jam.md)");
  cmd->add_option("--fraction", args->fraction,
                  "F: a packing fraction below the method's dense one, within 0.002, the radii as requested "
                  "(no contacts: docs/fraction.md)");
  cmd->add_option("--count", args->count,
                  "N: stop after N disks, a compact region: --method open fills from the bottom, closed from the "
                  "start point");
  cmd->add_option("--height", args->height, "H: fill only the part of the domain below y = H");
  cmd->add_flag("--progress", args->progress,
                "show the progress line even when stderr is not a terminal (one line per phase, for logs)");
  cmd->add_flag("-q,--quiet", args->quiet, "print nothing but errors (no summary, no progress line)");
  cmd->footer(
      "Example:\n"
      "  frontpack fill shapes/plate_with_holes.wkt --radius uniform:0.005,0.02 --seed 7 \\\n"
      "      -o packing.csv -o packing.data -o packing.png --json summary.json\n"
      "Prints a summary on stderr (disks, packing fraction overall and interior, radii, certificate, time);\n"
      "on a terminal, runs longer than half a second show a progress bar. Ctrl-C (or SIGTERM) stops the\n"
      "run within a second (exit 130 or 143) and leaves every output file as it was.");
  return {cmd, [args] { return run_fill(*args); }};
}

}  // namespace frontpack_tool::cli
