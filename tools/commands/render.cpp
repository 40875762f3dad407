// `frontpack render`: draw a packing (PNG, SVG, PDF).
#include <CLI/CLI.hpp>

#include <array>
#include <iostream>
#include <memory>
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

struct RenderArgs {
  PackingInputs in;
  std::vector<std::string> outputs;
  std::string format;
  std::string radius;
  int width = 1200;
  bool no_histogram = false;
  bool images = false;
  bool cells = false;
  std::string cells_range;
  bool quiet = false;
};

int run_render(RenderArgs& a) {
  resolve(a.in);
  frontpack_tool::RenderOptions picture;
  picture.width_px = a.width;
  picture.histogram = !a.no_histogram;
  picture.images = a.images;
  if (!a.cells_range.empty()) {
    const std::vector<double> ends = finite_numbers("--cells-range", a.cells_range, "LO,HI");
    if (ends.size() != 2 || !(ends[0] < ends[1])) {
      throw frontpack::OptionError(given_value("--cells-range", a.cells_range) + ": expected LO,HI with LO < HI");
    }
    picture.cells_range = std::array<double, 2>{ends[0], ends[1]};
  }
  if (!a.radius.empty()) {
    picture.requested = frontpack::parse_radii(a.radius);
    picture.requested_spec = a.radius;
  }
  const std::vector<frontpack_tool::Output> outputs = frontpack_tool::resolve_outputs(a.outputs, a.format, true);
  frontpack_tool::check_files(input_uses(a.in), output_uses(outputs, {}));
  const frontpack::Domain domain = load(a.in.domain);
  const std::vector<frontpack::Disk> disks = read_disks(a.in);
  if (a.cells) {
    // The cell coverage alone (exact areas, no sampling).
    frontpack::StatsOptions so;
    so.samples = 0;
    so.contacts = false;
    so.empty_circle = false;
    so.holes = false;
    so.coverage_profile = false;
    so.stop = stop_token();
    picture.cells = frontpack::measure(domain, disks, so).cell_coverage;
    picture.histogram = false;
  }
  frontpack_tool::PendingOutputs pending;
  for (const auto& o : outputs) {
    pending.write(o, domain, disks, picture, stop_token());
  }
  pending.commit_all(stop_token());
  if (!a.quiet) {
    for (const auto& o : outputs) {
      std::cerr << "wrote:       " << o.path.string() << " (" << frontpack_tool::format_name(o.format) << ", "
                << a.width << " x " << frontpack_tool::picture_height(domain, a.width, picture.histogram) << ", "
                << disks.size() << " disks"
                << (picture.cells ? ", " + frontpack_tool::cells_key(*picture.cells, picture.cells_range) : "")
                << ")\n";
    }
  }
  return ok;
}

}  // namespace

Command add_render(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Draw a packing: PNG, SVG or PDF, disks coloured by radius");
  add_packing_inputs(*cmd, args->in);
  cmd->add_option("-o,--output", args->outputs, "picture file(s): " + frontpack_tool::extensions_help(true))
      ->required();
  cmd->add_option("--format", args->format, frontpack_tool::format_names_help(true) + " instead of the extension");
  cmd->add_option("--width", args->width, "width in pixels (height: the domain's, plus the histogram)")
      ->capture_default_str();
  cmd->add_option("--radius", args->radius,
                  "the requested radius distribution (a --radius SPEC of fill): drawn over the histogram, "
                  "with the KS distance by area");
  cmd->add_flag("--no-histogram", args->no_histogram,
                "the packing alone, without the size-distribution panel below it");
  cmd->add_flag("--images", args->images,
                "with --periodic: also draw, lighter, the images of the disks that cross a periodic side")
      ->needs(args->in.domain.periodic_option);
  CLI::Option* cells =
      cmd->add_flag("--cells", args->cells,
                    "draw the coverage of the interior cells of side 8 rmax instead of the disks (dark: the least, "
                    "light: the largest; seams and sparse patches show dark), without the panel");
  cmd->add_option("--cells-range", args->cells_range,
                  "with --cells: LO,HI, the coverage drawn darkest and lightest instead of the map's own least and "
                  "largest (beyond them, as dark or as light), so that maps of different packings compare")
      ->needs(cells);
  cmd->add_flag("-q,--quiet", args->quiet, "print nothing but errors");
  cmd->footer(
      "Example:\n"
      "  frontpack fill shapes/plate_with_holes.wkt --radius uniform:0.005,0.02 -o packing.csv\n"
      "  frontpack render shapes/plate_with_holes.wkt packing.csv -o packing.png --width 800 \\\n"
      "      --radius uniform:0.005,0.02\n"
      "Below the packing, a histogram of the radii by area (bars coloured as the disks: the colour key), the\n"
      "requested distribution's area per bin as a line and the KS distance by area; --no-histogram omits it.");
  return {cmd, [args] { return run_render(*args); }};
}

}  // namespace frontpack_tool::cli
