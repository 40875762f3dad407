#include "outputs.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <unordered_set>
#include <utility>

#include "frontpack/errors.hpp"
#include "option_values.hpp"

namespace frontpack_tool {

namespace {

// The process-wide output lock and the batches not yet destroyed (see PendingOutputs).
std::mutex& output_lock() {
  static std::mutex m;
  return m;
}

std::vector<PendingOutputs*>& live_batches() {
  static std::vector<PendingOutputs*> batches;
  return batches;
}

// The directories make_output_directory made, parents first, and whether any batch was committed
// (then they hold the run's outputs and stay). Both under the output lock.
std::vector<std::filesystem::path>& new_directories() {
  static std::vector<std::filesystem::path> made;
  return made;
}

bool& some_batch_committed() {
  static bool committed = false;
  return committed;
}

// Removes the new directories that are empty, deepest first; the caller holds the output lock.
void remove_new_directories_locked() noexcept {
  auto& made = new_directories();
  if (!some_batch_committed()) {
    for (auto it = made.rbegin(); it != made.rend(); ++it) {
      (void)::rmdir(it->c_str());  // fails, harmlessly, on a directory that is not empty
    }
  }
  made.clear();
}

}  // namespace

namespace {

// The tool's pictures by the names of their rows in the table of formats, which holds their
// extensions (tests/formats_test.cpp: every picture row the tool writes has one).
constexpr std::pair<std::string_view, Picture> kPictures[] = {
    {"png", Picture::png}, {"svg", Picture::svg}, {"pdf", Picture::pdf}};

frontpack::FormatUse use_of(bool pictures_only) {
  return pictures_only ? frontpack::FormatUse::tool_pictures : frontpack::FormatUse::tool_writes;
}

}  // namespace

std::string format_name(const OutputFormat& f) {
  if (const auto* picture = std::get_if<Picture>(&f)) {
    for (const auto& [name, p] : kPictures) {
      if (p == *picture) {
        return std::string(name);
      }
    }
    return "unknown";
  }
  return frontpack::to_string(std::get<frontpack::Format>(f));
}

OutputFormat output_format(const frontpack::FileFormat& row) {
  if (row.tool_writes && row.holds == frontpack::FileKind::picture) {
    for (const auto& [name, p] : kPictures) {
      if (name == row.name) {
        return p;
      }
    }
  } else if (row.tool_writes && row.written_as) {
    return *row.written_as;
  }
  throw std::logic_error("the frontpack tool does not write " + std::string(row.name) + " files");
}

std::string format_names_help(bool pictures_only) {
  return frontpack::format_names(use_of(pictures_only));
}

std::string extensions_help(bool pictures_only) {
  return frontpack::format_extensions(use_of(pictures_only));
}

namespace {

// --format NAME (for every output) or the extension. Pictures (png, svg, pdf) are drawn by the
// tool's renderer, so that fill and render draw the same picture.
OutputFormat resolve_format(const std::filesystem::path& path, const std::string& name, bool pictures_only) {
  const frontpack::FormatUse use = use_of(pictures_only);
  if (!name.empty()) {
    if (const frontpack::FileFormat* row = frontpack::find_format_by_name(name, use)) {
      return output_format(*row);
    }
    throw frontpack::OptionError(cli::given_value("--format", name) + ": unknown format; expected " +
                                 frontpack::format_names(use));
  }
  if (const frontpack::FileFormat* row = frontpack::find_format_by_extension(path, use)) {
    return output_format(*row);
  }
  const std::string ext = path.extension().string();
  if (pictures_only) {
    throw frontpack::OptionError("-o " + path.string() + ": unknown picture format '" + ext + "'; use " +
                                 frontpack::format_extensions(use) + " (or --format)");
  }
  throw frontpack::OptionError(
      "-o " + path.string() +
      (ext.empty() ? std::string(": no file extension to tell the format by") : ": unknown format '" + ext + "'") +
      "; use " + frontpack::format_extensions(use) + ", or --format NAME");
}

// Fails early (before a long run) when an output's directory does not take a new file.
void check_writable(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw frontpack::IoError(std::string("cannot write '") + path.string() + "': it is a directory", path.string());
  }
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
    return;  // a device or FIFO: written through, whatever its directory allows
  }
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) {
    dir = ".";
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    const int err = errno;
    throw frontpack::IoError(std::string("cannot write '") + path.string() + "': " + std::strerror(err), path.string());
  }
}

}  // namespace

std::vector<Output> resolve_outputs(const std::vector<std::string>& paths, const std::string& format,
                                    bool pictures_only) {
  std::vector<Output> out;
  for (const std::string& p : paths) {
    out.push_back({p, resolve_format(p, format, pictures_only)});
  }
  return out;
}

void check_files(const std::vector<FileUse>& inputs, const std::vector<FileUse>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (const FileUse& in : inputs) {
      if (frontpack::same_regular_file(in.path, outputs[i].path)) {
        throw UsageError("'" + outputs[i].path.string() + "' is given as the output " + outputs[i].use +
                         " and is the input " + in.use + " ('" + in.path.string() +
                         "'): writing it would destroy the input; choose another output file");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (frontpack::same_regular_file(outputs[j].path, outputs[i].path)) {
        throw UsageError("'" + outputs[i].path.string() + "' is given as two outputs, " + outputs[j].use + " '" +
                         outputs[j].path.string() + "' and " + outputs[i].use +
                         ": one would overwrite the other; choose another file for one of them");
      }
    }
  }
  for (const FileUse& o : outputs) {
    check_writable(o.path);
  }
}

void make_output_directory(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> missing;
  std::error_code ec;
  for (std::filesystem::path p = dir; !p.empty() && !std::filesystem::exists(p, ec);) {
    missing.push_back(p);
    const std::filesystem::path parent = p.parent_path();
    if (parent == p) {
      break;
    }
    p = parent;
  }
  {
    const std::lock_guard<std::mutex> lock(output_lock());
    auto& made = new_directories();
    made.insert(made.end(), missing.rbegin(), missing.rend());
  }
  std::filesystem::create_directories(dir);
}

void remove_new_directories() noexcept {
  const std::lock_guard<std::mutex> lock(output_lock());
  remove_new_directories_locked();
}

PendingOutputs::~PendingOutputs() {
  const std::lock_guard<std::mutex> lock(output_lock());
  files_.clear();  // each OutputFile removes its temporary file unless committed
  auto& batches = live_batches();
  batches.erase(std::remove(batches.begin(), batches.end(), this), batches.end());
}

frontpack::OutputFile& PendingOutputs::open(const std::filesystem::path& path) {
  // Opening a FIFO waits for its reader: outside the lock, so that the signal watcher can still
  // take it (a FIFO has no temporary file to register). Everything else is created and registered
  // under the lock, so that no temporary file exists unregistered.
  struct stat st {};
  std::unique_ptr<frontpack::OutputFile> fifo;
  if (::stat(path.c_str(), &st) == 0 && S_ISFIFO(st.st_mode)) {
    fifo = std::make_unique<frontpack::OutputFile>(path);
  }
  const std::lock_guard<std::mutex> lock(output_lock());
  auto& batches = live_batches();
  if (std::find(batches.begin(), batches.end(), this) == batches.end()) {
    batches.push_back(this);
  }
  files_.push_back(fifo ? std::move(fifo) : std::make_unique<frontpack::OutputFile>(path));
  return *files_.back();
}

void PendingOutputs::write(const Output& output, const frontpack::Domain& domain,
                           std::span<const frontpack::Disk> disks, const RenderOptions& picture, std::stop_token stop,
                           std::span<const std::uint32_t> types) {
  frontpack::OutputFile& file = open(output.path);
  if (const auto* format = std::get_if<Picture>(&output.format)) {
    RenderOptions options = picture;
    options.stop = std::move(stop);
    render(file, *format, domain, disks, options);
  } else {
    frontpack::WriteOptions options;
    options.svg.width_px = picture.width_px;
    options.types = types;
    options.stop = std::move(stop);
    frontpack::write(file.stream(), std::get<frontpack::Format>(output.format), domain, disks, options);
  }
}

void PendingOutputs::write_text(const std::filesystem::path& path, const std::string& text) {
  frontpack::OutputFile& file = open(path);
  file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
}

void PendingOutputs::commit_all(const std::stop_token& stop) {
  const std::lock_guard<std::mutex> lock(output_lock());
  if (stop.stop_requested()) {
    throw frontpack::CancelledError();
  }
  for (const auto& file : files_) {
    committed_ = true;
    some_batch_committed() = true;
    file->commit();
  }
}

bool PendingOutputs::remove_temporaries_now() noexcept {
  output_lock().lock();  // held until the process exits: no commit may start
  bool committed = false;
  for (PendingOutputs* batch : live_batches()) {
    committed = committed || batch->committed_;
    for (const auto& file : batch->files_) {
      if (!file->temporary().empty()) {
        ::unlink(file->temporary().c_str());
      }
    }
  }
  remove_new_directories_locked();
  return committed;
}

}  // namespace frontpack_tool
