// The tool's outputs: which files a command writes, the checks made before any work, and the
// batch that makes them appear together at the end, or not at all.
//
// Every output goes through frontpack::OutputFile (regular files replaced atomically, devices,
// FIFOs and /dev/stdout written through). A command writes each output to its temporary file and
// commits the whole batch last, after every computation: a failure or a signal before that point
// leaves every target as it was (a FIFO or device may have received part of its bytes); once the
// batch is committed the run is complete.
#pragma once

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <stop_token>
#include <string>
#include <variant>
#include <vector>

#include "frontpack/formats.hpp"
#include "frontpack/io.hpp"
#include "frontpack/output_file.hpp"
#include "render.hpp"

namespace frontpack_tool {

/// A mistake in the command line that is not CLI11's to find (the same file given for two uses):
/// exit code 1, like CLI11's own usage errors.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using OutputFormat = std::variant<frontpack::Format, Picture>;

struct Output {
  std::filesystem::path path;
  OutputFormat format;
};

/// "csv", "png", ...: the format's name in the table of formats (frontpack/formats.hpp).
[[nodiscard]] std::string format_name(const OutputFormat& format);

/// The output format of a row of the table of formats that the tool writes (FormatUse::tool_writes):
/// a picture (drawn with Cairo) or the library's format. Throws std::logic_error for a row the tool
/// does not write.
[[nodiscard]] OutputFormat output_format(const frontpack::FileFormat& row);

/// Help texts from the table of formats, for a command that writes every format the tool writes
/// (fill) or pictures only (render): the --format names ("csv, yade, ... or pdf") and the
/// extensions of -o (".csv, .txt or .yade (Yade), ...").
[[nodiscard]] std::string format_names_help(bool pictures_only);
[[nodiscard]] std::string extensions_help(bool pictures_only);

/// The format of each -o PATH: --format NAME for all of them, else each one's extension, both by
/// the table of formats (names and extensions in any case); with `pictures_only`, PNG, SVG and PDF
/// only. Throws frontpack::OptionError naming the path and the formats known.
[[nodiscard]] std::vector<Output> resolve_outputs(const std::vector<std::string>& paths, const std::string& format,
                                                  bool pictures_only);

/// A file a command reads or writes, and the option or argument that names it ("DOMAIN", "-o").
struct FileUse {
  std::string use;
  std::filesystem::path path;
};

/// Refuses, before any work, a command line that would clobber its own files: the same regular
/// file given as two outputs, or an input given as an output (frontpack::same_regular_file).
/// Then checks that every output's directory takes a new file (a long run must not fail at its
/// end for a typo in a directory). Throws UsageError naming both uses, or frontpack::IoError.
void check_files(const std::vector<FileUse>& inputs, const std::vector<FileUse>& outputs);

/// Makes `dir` and its missing parents for a command's outputs (a deck's directory), before the
/// run so that its outputs can be checked and written there. The directories it makes are the
/// run's own: unless an output batch is committed, remove_new_directories() takes them away again
/// (those still empty, deepest first), as the signal watcher's last resort does. Throws
/// std::filesystem::filesystem_error.
void make_output_directory(const std::filesystem::path& dir);

/// On a run's way out: removes the directories make_output_directory made, unless some output
/// batch was committed (a run that writes nothing leaves no new directory). Never throws.
void remove_new_directories() noexcept;

/// The outputs of one command, written one by one and committed together. Thread-safe against
/// the signal watcher: open() and commit_all() hold the process-wide output lock, and
/// remove_temporaries_now() takes it, so a signal can never find a temporary file half-registered
/// or remove one that is being renamed.
class PendingOutputs {
 public:
  PendingOutputs() = default;
  PendingOutputs(const PendingOutputs&) = delete;
  PendingOutputs& operator=(const PendingOutputs&) = delete;
  /// Discards (removes the temporary files of) everything not committed.
  ~PendingOutputs();

  /// Opens the next output (frontpack::OutputFile); the reference stays valid until destruction.
  frontpack::OutputFile& open(const std::filesystem::path& path);
  /// Writes a data format (with the disks' types, if any) or draws a picture into a new output.
  void write(const Output& output, const frontpack::Domain& domain, std::span<const frontpack::Disk> disks,
             const RenderOptions& picture, std::stop_token stop, std::span<const std::uint32_t> types = {});
  /// Writes text (a JSON summary) into a new output.
  void write_text(const std::filesystem::path& path, const std::string& text);
  /// Commits every output in order, unless `stop` was requested first (then throws
  /// frontpack::CancelledError and nothing is committed). Throws frontpack::IoError from a failed
  /// commit; the outputs committed before it stay.
  void commit_all(const std::stop_token& stop);

  /// For the signal watcher's last resort: removes the temporary files of every batch not yet
  /// committed (and, if none was, the directories make_output_directory made), and keeps holding
  /// the lock so that no commit can start. Returns whether some
  /// batch was committed before. Never throws; never returns the lock (the caller exits).
  static bool remove_temporaries_now() noexcept;

 private:
  std::vector<std::unique_ptr<frontpack::OutputFile>> files_;
  bool committed_ = false;
};

}  // namespace frontpack_tool
