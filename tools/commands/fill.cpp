// `frontpack fill`: fill a domain, write the packing, print the summary.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
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

struct FillArgs {
  DomainSource src;
  // The fill options (frontpack/options.hpp) by name: the text given ("" if not), and for each
  // flag whether it was given.
  std::map<std::string, std::string, std::less<>> option_text;
  std::map<std::string, bool, std::less<>> option_flag;
  std::vector<std::string> outputs;
  std::string format;
  std::string json;
  int width = 1200;
  bool no_histogram = false;
  bool holes = false;
  bool quiet = false;
  bool progress = false;
  std::string types;                // --types RULE
  std::vector<std::string> deck{};  // --deck SIMULATOR DIR
  std::string density;              // --density SPEC
  std::string thickness;            // --thickness T
  std::string wall_radius;          // --wall-radius W
  [[nodiscard]] const std::string& radius() const { return option_text.at("radius"); }
};

// The fill options given, each read by the library's parser; a flag sets its option to the
// opposite of the default. The Budget's options come from the DomainSource (every command's).
frontpack::FillOptions parse_fill_options(const FillArgs& a, const frontpack::Budget& limits) {
  frontpack::FillOptions options;
  for (const frontpack::OptionInfo& info : frontpack::fill_option_list()) {
    const std::string name(info.name);
    if (info.budget) {
      continue;
    }
    if (info.kind == frontpack::OptionKind::flag) {
      if (a.option_flag.at(name)) {
        frontpack::set_option(options, info, !std::get<bool>(frontpack::default_value(info)));
      }
    } else if (const std::string& text = a.option_text.at(name); !text.empty()) {
      frontpack::set_option(options, info, frontpack::parse_option(info, text, frontpack::flag_name(info)));
    }
  }
  options.max_disks = limits.max_count;
  options.memory_limit = limits.memory_limit;
  options.stop = stop_token();
  return options;
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
         {"radius_spec_given", !a.radius().empty()},
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

// What a run needs once its command line is read and checked: the options, the outputs and the
// deck planned, the files checked, the domain loaded and the options checked against it.
struct FillPlan {
  std::string spec;  // the radius spec, given or the default
  frontpack::FillOptions options;
  frontpack::Budget limits;
  std::vector<frontpack_tool::Output> outputs;
  frontpack::TypeRule type_rule;
  DeckPlan deck;
  frontpack::DomainFile file;
};

// The files a run reads and writes, checked before any work (no output overwrites an input); the
// deck's directory is made here (and removed again if the run commits nothing).
void check_run_files(const FillArgs& a, const std::string& spec, const std::vector<frontpack_tool::Output>& outputs,
                     const frontpack::TypeRule& type_rule, const DeckPlan& deck) {
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
}

FillPlan plan_fill(const FillArgs& a) {
  std::string spec = a.radius().empty() ? frontpack::default_text(frontpack::fill_option("radius")) : a.radius();
  const frontpack::Budget limits = budget(a.src);
  frontpack::FillOptions options = parse_fill_options(a, limits);
  std::vector<frontpack_tool::Output> outputs = frontpack_tool::resolve_outputs(a.outputs, a.format, false);
  frontpack::TypeRule type_rule = a.types.empty() ? frontpack::TypeRule{} : frontpack::parse_type_rule(a.types);
  DeckPlan deck = plan_deck(a, type_rule.count());
  deck.options.stop = options.stop;
  deck.options.budget = limits;
  check_run_files(a, spec, outputs, type_rule, deck);
  // Curves become polylines within a tenth of the smallest radius of the domain's true boundary.
  frontpack::DomainFile file = load_file(a.src, options.radii.min() / 10);
  frontpack::check_options(file.domain, options);
  return FillPlan{.spec = std::move(spec),
                  .options = std::move(options),
                  .limits = limits,
                  .outputs = std::move(outputs),
                  .type_rule = std::move(type_rule),
                  .deck = std::move(deck),
                  .file = std::move(file)};
}

// The generator, with the progress line; none if no disk fits (said on stderr).
std::optional<frontpack::Packing> run_generator(const FillPlan& plan, frontpack_tool::ProgressLine& line) {
  frontpack::Generator generator(plan.file.domain, plan.options);
  generator.on_progress([&line](const frontpack::Progress& progress) {
    line.update(progress);
    return true;
  });
  try {
    return generator.run();
  } catch (const frontpack::NothingFitsError& e) {
    line.clear();
    std::cerr << "frontpack: " << e.what() << "; nothing written\n";
    return std::nullopt;
  }
}

// What the report of a run shows and writes, besides the packing.
struct FillResult {
  frontpack::PackingStats stats;
  double seconds_stats = 0;
  std::vector<std::uint32_t> types;
  std::vector<std::size_t> per_type;  // disks per type: [k] for type k + 1
  std::vector<std::string> deck_files;
};

// Statistics only where they are shown or written: the text summary shows the fractions and
// the radii only; the JSON summary has the contacts and the quality measures too (empty circle,
// coverage profile and cells: about 0.6 s per million disks), and the hole counts (about 3 s
// more) only with --holes (`frontpack stats` shows them).
void measure_packing(const FillArgs& a, const FillPlan& plan, const frontpack::Packing& p,
                     frontpack_tool::ProgressLine& line, FillResult& r) {
  const auto t_stats = Clock::now();
  if (!a.quiet || !a.json.empty()) {
    line.phase("measuring " + std::to_string(p.disks.size()) + " disks");
    const bool quality = !a.json.empty();
    r.stats =
        frontpack::measure(plan.file.domain, p.disks,
                           {.requested = quality ? std::optional<frontpack::Radii>(plan.options.radii) : std::nullopt,
                            .samples = quality ? StatsSamples::json : StatsSamples::text,
                            .histogram_bins = quality ? frontpack::StatsOptions{}.histogram_bins : 0,
                            .contacts = quality,
                            .empty_circle = quality,
                            .holes = quality && a.holes,
                            .coverage_profile = quality,
                            .cell_coverage = quality,
                            .budget = plan.limits,
                            .stop = plan.options.stop});
  }
  r.seconds_stats = seconds_since(t_stats);
  r.types = a.types.empty() ? std::vector<std::uint32_t>{} : frontpack::assign_types(plan.type_rule, p.disks);
  for (const std::uint32_t t : r.types) {
    r.per_type.resize(std::max<std::size_t>(r.per_type.size(), t), 0);
    ++r.per_type[t - 1];
  }
}

// Every output, the deck and the JSON summary, written to temporary files and committed together.
void write_outputs(const FillArgs& a, const FillPlan& plan, const frontpack::Packing& p,
                   frontpack_tool::ProgressLine& line, FillResult& r, Clock::time_point t_start) {
  const frontpack::Domain& domain = plan.file.domain;
  frontpack_tool::PendingOutputs pending;
  const frontpack_tool::RenderOptions picture{.width_px = a.width,
                                              .histogram = !a.no_histogram,
                                              .requested = plan.options.radii,
                                              .requested_spec = plan.spec,
                                              .stop = plan.options.stop};
  for (const auto& o : plan.outputs) {
    line.phase("writing " + o.path.string());
    pending.write(o, domain, p.disks, picture, plan.options.stop, r.types);
  }
  if (plan.deck.wanted) {
    line.phase("writing the " + std::string(frontpack::to_string(plan.deck.options.simulator)) + " deck in " +
               plan.deck.dir.string());
    for (const frontpack::DeckFile& f : frontpack::make_deck(domain, p.disks, r.types, plan.deck.options)) {
      r.deck_files.push_back((plan.deck.dir / f.name).string());
      pending.write_text(plan.deck.dir / f.name, f.text);
    }
  }
  if (!a.json.empty()) {
    Json j = fill_json(a, plan.spec, plan.options, domain, p, r.stats, plan.outputs, r.seconds_stats,
                       seconds_since(t_start));
    if (!plan.file.curves.empty()) {
      j["domain"]["curves"] = curves_json(plan.file);
    }
    if (plan.file.format == frontpack::DomainFormat::dxf) {
      j["domain"]["units"] = plan.file.units;  // "" when the file states none
    }
    if (!r.types.empty()) {
      j["types"] = Json{{"rule", a.types}, {"disks_per_type", r.per_type}};
    }
    if (plan.deck.wanted) {
      j["deck"] = Json{{"simulator", a.deck[0]}, {"directory", plan.deck.dir.string()}, {"files", r.deck_files}};
    }
    pending.write_text(a.json, j.dump(2) + "\n");
  }
  line.phase("committing the outputs");
  pending.commit_all(plan.options.stop);
  line.clear();
}

// The text summary on stderr: the packing, its certificate and time, and the files written.
void print_summary(const FillArgs& a, const FillPlan& plan, const frontpack::Packing& p, const FillResult& r) {
  const frontpack::Certificate& c = p.certificate;
  const frontpack::FillOptions& options = plan.options;
  const double seconds_fill =
      p.stats.seconds_front + p.stats.seconds_jam + p.stats.seconds_cull + p.stats.seconds_overlap;
  std::cerr << "disks:       " << p.disks.size() << " (" << frontpack::to_string(options.method) << " form, seed "
            << options.seed << (p.truncated ? ", truncated at --max-disks" : "") << ")\n"
            << "radius:      " << plan.spec << (a.radius().empty() ? " (the default; set with --radius)" : "") << "\n"
            << "fraction:    " << frontpack_tool::fraction_line(r.stats) << "\n"
            << "radii:       " << frontpack_tool::radii_line(r.stats.sizes) << "\n"
            << (p.target ? "target:      " + frontpack_tool::target_line(*p.target) + "\n" : std::string())
            << "certificate: " << (c.dropped == 0 ? "certified" : "certified after repair") << ": " << c.generated
            << " generated, " << c.culled << " culled (not inside), " << c.dropped
            << " dropped (overlap); every decision exact\n"
            << (options.jam ? "jam:         " + std::to_string(p.stats.jam_inserted) + " disks inserted in " +
                                  std::to_string(p.stats.jam_rounds) + " rounds, " + std::to_string(p.stats.jam_steps) +
                                  " relaxation steps\n"
                            : std::string())
            << "time:        " << fmt(seconds_fill) << " s (front " << fmt(p.stats.seconds_front)
            << (options.jam ? ", jam " + fmt(p.stats.seconds_jam) : std::string()) << ", cull "
            << fmt(p.stats.seconds_cull) << ", overlap pass " << fmt(p.stats.seconds_overlap) << "), statistics "
            << fmt(r.seconds_stats) << " s\n"
            << units_line(plan.file) << curve_lines(plan.file, 10);
  if (!r.types.empty()) {
    std::cerr << "types:       " << r.per_type.size() << " (" << a.types << "):";
    for (std::size_t k = 0; k < r.per_type.size(); ++k) {
      std::cerr << (k == 0 ? " " : ", ") << r.per_type[k] << " of type " << k + 1;
    }
    std::cerr << "\n";
  }
  for (const auto& o : plan.outputs) {
    std::cerr << "wrote:       " << o.path.string() << " (" << frontpack_tool::format_name(o.format) << ")\n";
  }
  if (!a.json.empty()) {
    std::cerr << "wrote:       " << a.json << " (summary)\n";
  }
  for (const std::string& f : r.deck_files) {
    std::cerr << "wrote:       " << f << " (" << a.deck[0] << " deck)\n";
  }
}

int run_fill(const FillArgs& a) {
  const auto t_start = Clock::now();
  const FillPlan plan = plan_fill(a);
  frontpack_tool::ProgressLine line(frontpack_tool::ProgressLine::mode_for(!a.quiet, a.progress));
  const std::optional<frontpack::Packing> run = run_generator(plan, line);
  if (!run) {
    return nothing_fits;
  }
  const frontpack::Packing& p = *run;
  FillResult result;
  measure_packing(a, plan, p, line, result);
  write_outputs(a, plan, p, line, result, t_start);
  if (!a.quiet) {
    print_summary(a, plan, p, result);
  }
  if (p.truncated) {
    std::cerr << "frontpack: stopped at --max-disks " << plan.options.max_disks << ": the packing written ("
              << p.disks.size() << (p.disks.size() == 1 ? " disk" : " disks")
              << ", certified) does not fill the domain\n";
    return max_disks_reached;
  }
  return ok;
}

// The fill options' flags, one per option of the description but the Budget's (every command's,
// add_domain_options): a flag for each on/off option, a value for the others.
void add_fill_options(CLI::App& cmd, FillArgs& args) {
  for (const frontpack::OptionInfo& info : frontpack::fill_option_list()) {
    const std::string name(info.name);
    if (info.budget) {
      continue;
    }
    if (info.kind == frontpack::OptionKind::flag) {
      cmd.add_flag(frontpack::flag_name(info), args.option_flag[name], option_help(info));
    } else {
      cmd.add_option(frontpack::flag_name(info), args.option_text[name], option_help(info));
    }
  }
}

}  // namespace

Command add_fill(CLI::App& app) {
  auto args = std::make_shared<FillArgs>();
  CLI::App* cmd = app.add_subcommand("fill", "Fill a domain with disks (advancing front, certified exactly)");
  add_domain_options(*cmd, args->src);
  add_periodic_options(*cmd, args->src);
  cmd->get_option("DOMAIN")->excludes(args->src.periodic_option);
  args->src.periodic_option->excludes(cmd->get_option("DOMAIN"));
  add_fill_options(*cmd, *args);
  cmd->add_option("-o,--output", args->outputs,
                  "output file, any number; format by extension: " + frontpack_tool::extensions_help(false));
  cmd->add_option("--format", args->format,
                  "format of every -o instead of the extension: " + frontpack_tool::format_names_help(false));
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
