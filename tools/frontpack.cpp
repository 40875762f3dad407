// The frontpack command-line tool. It maps library errors to messages and exit codes; the
// library itself never prints.
//
// Exit codes (also in `frontpack --help` and the README):
//   0 success, 1 usage error (unknown option, missing argument, a file given for two uses),
//   2 unreadable input or unwritable output file, 3 WKT syntax, unsupported geometry or entity,
//   open contour (DXF, GeoJSON, Shapefile), 4 invalid domain, 5 invalid option (radius, method, format, width, seed,
//   limit), 6 packing not certified (check: overlaps or disks outside), 7 malformed disk file, 8 no disk fits (fill:
//   nothing written), 9 stopped at --max-disks (fill: the certified partial packing is written), 70 internal error, 128
//   + N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP; nothing written).
//
// Files (tools/outputs.hpp): outputs are written to temporary files and committed together at
// the end, so a failed or interrupted run leaves every file as it was; /dev/stdout, devices and
// FIFOs are written through; a file given for two uses is refused before any work.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "outputs.hpp"
#include "signals.hpp"

int main(int argc, char** argv) {
  frontpack_tool::SignalWatch signals;  // first: every later thread inherits the blocked signals
  frontpack_tool::cli::set_signal_watch(&signals);
  CLI::App app{"frontpack: dense, exactly certified disk packings of polygonal domains", "frontpack"};
  app.set_version_flag("--version", std::string(frontpack::version_string));
  app.require_subcommand(1);
  app.footer(std::string("Run 'frontpack SUBCOMMAND --help' for a worked example of each.\n\n") +
             frontpack_tool::cli::kExitCodes);

  const std::vector<frontpack_tool::cli::Command> commands = {
      frontpack_tool::cli::add_info(app), frontpack_tool::cli::add_fill(app), frontpack_tool::cli::add_check(app),
      frontpack_tool::cli::add_render(app), frontpack_tool::cli::add_stats(app)};

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? frontpack_tool::cli::ok : frontpack_tool::cli::usage;
  }

  try {
    for (const frontpack_tool::cli::Command& command : commands) {
      if (*command.app) {
        frontpack_tool::cli::refuse_empty_values(*command.app);
        const int code = command.run();
        if (code != frontpack_tool::cli::ok) {
          frontpack_tool::remove_new_directories();
        }
        return code;
      }
    }
    return frontpack_tool::cli::usage;
  } catch (const CLI::ParseError& e) {
    frontpack_tool::remove_new_directories();
    std::cerr << "frontpack: " << e.what() << "\n";
    return frontpack_tool::cli::usage;
  } catch (const frontpack::CancelledError&) {
    frontpack_tool::remove_new_directories();
    std::cerr << "\nfrontpack: interrupted by " << frontpack_tool::signal_name(signals.signal())
              << "; no output written\n";
    return signals.exit_code();
  } catch (const std::exception& e) {
    frontpack_tool::remove_new_directories();
    const int code = frontpack_tool::cli::exit_code(e);
    std::cerr << "frontpack: " << (code == frontpack_tool::cli::internal ? "internal error: " : "") << e.what() << "\n";
    return code;
  }
}
