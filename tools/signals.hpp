// SIGINT, SIGTERM and SIGHUP: the run stops within a second, leaves no temporary file and no
// partial output, and exits with 128 + the signal's number (130, 143, 129).
//
// The signals are blocked in every thread and taken by one watcher thread (sigwait), which
// requests a stop on a std::stop_source: the library polls its token in every long loop and
// throws frontpack::CancelledError, the tool unwinds (each pending output removes its temporary
// file) and exits. Should the run not have ended after a grace period (blocked opening a FIFO that
// has no reader, in a long sort), or at a second signal, the watcher removes the temporary files
// itself (PendingOutputs::remove_temporaries_now) and ends the process.
#pragma once

#include <stop_token>

namespace frontpack_tool {

class SignalWatch {
 public:
  /// Blocks the signals in the calling thread (call it before any other thread exists, so that
  /// every thread inherits the mask) and starts the watcher. Signals ignored at start (nohup, a
  /// background job) stay ignored.
  SignalWatch();
  SignalWatch(const SignalWatch&) = delete;
  SignalWatch& operator=(const SignalWatch&) = delete;
  /// The watcher is detached: the process may exit while it waits.
  ~SignalWatch() = default;

  /// The token every library call of the run gets.
  [[nodiscard]] std::stop_token token() const;
  /// The signal that stopped the run, or 0.
  [[nodiscard]] int signal() const noexcept;
  /// The exit code for a stopped run: 128 + the signal (130 for a stop without a signal).
  [[nodiscard]] int exit_code() const noexcept;
};

/// "SIGINT", "SIGTERM", "SIGHUP", or "signal N".
[[nodiscard]] const char* signal_name(int signal) noexcept;

}  // namespace frontpack_tool
