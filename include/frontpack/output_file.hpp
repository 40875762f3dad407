// frontpack: an output file that appears whole or not at all, and goes where the user pointed.
//
// The one implementation of output files in frontpack: the library's write_file() and every file
// the frontpack tool writes (data formats, pictures, JSON summaries) go through it.
//
// Where the bytes go, decided once when the OutputFile is made:
//   - "/dev/stdout", "/dev/stderr", "/dev/fd/N" and "/proc/self/fd/N" write to the descriptor the
//     process already has (a duplicate of it, sharing its offset: a shell's `>` and `>>` keep
//     their meaning). Nothing is created, renamed or truncated.
//   - A path that is, or whose symlinks lead to, anything but a regular file (a character or
//     block device such as /dev/null or /dev/full, a FIFO, a socket) is opened and written
//     through. Nothing is replaced.
//   - Otherwise (a regular file, or no file yet): the bytes go to a new temporary file in the
//     directory of the final target (symlinks followed, so a link stays a link and its target gets
//     the data), created exclusively as ".NAME.frontpack-PID-K.tmp". commit() flushes it, syncs it
//     to disk and renames it over the target in one step: readers see the old file or the complete
//     new one, never a partial file. The new file gets the permissions of the file it replaces, or
//     those of a new file (0666 less the umask) where there was none.
// Write-through outputs are not atomic: a reader of a FIFO sees the bytes as they are written,
// and a failed or cancelled run may have written part of them.
//
// Errors: IoError naming the path as given and the operating system's reason, from the
// constructor (the directory cannot take a file, the path is a directory), from stream writes
// (reported by commit()), and from commit() itself (a full disk: ENOSPC).
#pragma once

#include <filesystem>
#include <memory>
#include <ostream>

namespace frontpack {

class OutputFile {
 public:
  /// Resolves `path` as above and opens the temporary file or the write-through target. Throws
  /// IoError.
  explicit OutputFile(std::filesystem::path path);
  OutputFile(OutputFile&&) noexcept;
  OutputFile& operator=(OutputFile&&) noexcept;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// Discards the output unless commit() succeeded: the temporary file is removed.
  ~OutputFile();

  /// The stream to write to. Write errors (EIO, ENOSPC, EPIPE) are remembered with the OS's
  /// reason and reported by commit().
  [[nodiscard]] std::ostream& stream();

  /// Flushes everything written; for an atomic output, syncs the temporary file to disk and
  /// renames it over the target. Throws IoError (with the first write error's reason) and then
  /// leaves the target as it was. May be called once.
  void commit();

  /// Removes the temporary file now (as the destructor does). Idempotent, never throws.
  void discard() noexcept;

  /// The path as given.
  [[nodiscard]] const std::filesystem::path& path() const noexcept;
  /// True when the output is a temporary file renamed over its target on commit(); false when it
  /// is written through (a descriptor, a device, a FIFO).
  [[nodiscard]] bool atomic() const noexcept;
  /// The temporary file (empty when written through or once committed or discarded), so that a
  /// caller that must exit at once (a second signal) can remove it.
  [[nodiscard]] const std::filesystem::path& temporary() const noexcept;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// The file an output path resolves to for identity checks: true if `a` and `b` name the same
/// regular file, or the same not-yet-existing path once symlinks and ".." are resolved. Two
/// outputs or an input and an output that are the same file clobber one another; devices and
/// FIFOs given twice do not count (their bytes are written through, in order).
[[nodiscard]] bool same_regular_file(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace frontpack
