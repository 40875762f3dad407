// `frontpack check`: certify any packing exactly and report the worst disks.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
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
#include "frontpack/frontpack.hpp"
#include "outputs.hpp"
#include "packing_inputs.hpp"
#include "render.hpp"
#include "report.hpp"

namespace frontpack_tool::cli {

namespace {

struct CheckArgs {
  PackingInputs in;
  std::string json;
  bool all = false;
  bool quiet = false;
};

std::string disk_text(const frontpack::Disk& d) {
  return std::string("centre (") + fmt(d.centre.x) + ", " + fmt(d.centre.y) + "), radius " + fmt(d.radius);
}

int run_check(CheckArgs& a) {
  resolve(a.in);
  frontpack_tool::check_files(input_uses(a.in), output_uses({}, a.json));
  const frontpack::Domain domain = load(a.in.domain);
  const std::vector<frontpack::Disk> disks = read_disks(a.in);
  const std::string domain_name = a.in.domain.name();
  const std::string& disk_file = a.in.disks;
  const frontpack::CertifyReport r = frontpack::certify(domain, disks, stop_token());
  const bool certified = r.outside.empty() && r.overlapping.empty();

  std::ostringstream out;
  out << "domain:      " << domain_name << " (area " << fmt(domain.area()) << ")\n"
      << "disks:       " << disks.size() << " in " << disk_file << " (" << disk_numbering(a.in) << ")\n";
  out << "outside:     " << r.outside.size() << (r.outside.size() == 1 ? " disk" : " disks")
      << " not entirely inside the domain";
  if (r.farthest_outside) {
    const std::size_t i = *r.farthest_outside;
    out << "; worst: disk " << i << " (" << disk_text(disks[i]) << ") reaches about " << fmt(r.farthest_outside_by)
        << " out of the domain";
  }
  out << "\n";
  out << "overlaps:    " << r.overlapping.size() << (r.overlapping.size() == 1 ? " pair" : " pairs")
      << " of overlapping disks";
  if (r.deepest_overlap) {
    const auto [i, j] = *r.deepest_overlap;
    out << "; worst: disks " << i << " and " << j << " overlap by about " << fmt(r.deepest_overlap_depth)
        << " (r_i + r_j - distance)";
  }
  out << "\n";
  if (!certified) {
    out << "             (which disks are outside and which pairs overlap is decided exactly; the 'about' "
           "figures are floating point)\n";
  }
  if (a.all) {
    for (const std::size_t i : r.outside) {
      out << "outside " << i << ": " << disk_text(disks[i]) << "\n";
    }
    for (const auto& [i, j] : r.overlapping) {
      out << "overlap " << i << " " << j << "\n";
    }
  }
  out << "result:      "
      << (certified ? "certified: no two disks overlap and every disk lies in the domain" : "NOT certified") << " ("
      << r.certificate.candidate_pairs << " candidate pairs, every decision exact)\n";
  frontpack_tool::PendingOutputs pending;
  if (!a.json.empty()) {
    Json j{{"frontpack_version", frontpack::version_string},
           {"command", "check"},
           {"domain", domain_name},
           {"disk_file", disk_file},
           {"disks", disks.size()},
           {"certified", certified}};
    j.update(frontpack_tool::certify_json(r));
    j["candidate_pairs"] = r.certificate.candidate_pairs;
    pending.write_text(a.json, j.dump(2) + "\n");
  }
  pending.commit_all(stop_token());
  if (!a.quiet) {
    std::cout << out.str();
  }
  if (!certified) {
    std::cerr << "frontpack: " << disk_file << " is not certified: " << r.overlapping.size() << " overlapping "
              << (r.overlapping.size() == 1 ? "pair" : "pairs") << ", " << r.outside.size()
              << (r.outside.size() == 1 ? " disk" : " disks") << " outside the domain\n";
    return not_certified;
  }
  return ok;
}

}  // namespace

Command add_check(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand("check", "Certify any packing exactly: no overlap, every disk inside");
  add_packing_inputs(*cmd, args->in);
  cmd->add_flag("--all", args->all, "list every disk outside and every overlapping pair");
  cmd->add_option("--json", args->json, "write the report as JSON to this file");
  cmd->add_flag("-q,--quiet", args->quiet, "print nothing but errors; the exit code tells");
  cmd->footer(
      "Example:\n"
      "  frontpack check shapes/l_shape.wkt packing.csv\n"
      "  frontpack check --wkt 'POLYGON((0 0, 2 0, 2 1, 0 1, 0 0))' after_run.data   (LAMMPS write_data)\n"
      "Exit 0 if certified, 6 if some pair overlaps or some disk is not entirely inside (the worst of each\n"
      "is named), 7 if the disk file is malformed (the line is named).");
  return {cmd, [args] { return run_check(*args); }};
}

}  // namespace frontpack_tool::cli
