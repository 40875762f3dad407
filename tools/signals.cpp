#include "signals.hpp"

#include <pthread.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <ctime>
#include <string>
#include <thread>

#include "outputs.hpp"

namespace frontpack_tool {

namespace {

std::stop_source& stop_source() {
  static std::stop_source source;
  return source;
}

std::atomic<int> g_signal{0};

// How long the run has to unwind by itself after the first signal. The library polls its stop
// token every few milliseconds; this is the bound for everything else.
constexpr long kGraceNanoseconds = 500'000'000;

void watch(sigset_t set) {
  int sig = 0;
  if (::sigwait(&set, &sig) != 0) {
    return;
  }
  g_signal.store(sig);
  stop_source().request_stop();
  // The run unwinds and exits; if it is still here after the grace period, or at a second signal,
  // end it from here.
  const timespec grace{0, kGraceNanoseconds};
  (void)::sigtimedwait(&set, nullptr, &grace);
  const bool committed = PendingOutputs::remove_temporaries_now();
  std::string message("\nfrontpack: interrupted by ");
  message.append(signal_name(sig));
  message.append(committed ? "; the outputs were written before it\n" : "; no output written\n");
  (void)::write(STDERR_FILENO, message.data(), message.size());
  ::_exit(128 + sig);
}

}  // namespace

SignalWatch::SignalWatch() {
  sigset_t set;
  sigemptyset(&set);
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (::sigaction(s, nullptr, &old) == 0 && old.sa_handler != SIG_IGN) {
      sigaddset(&set, s);
    }
  }
  ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread(watch, set).detach();
}

std::stop_token SignalWatch::token() const {
  return stop_source().get_token();
}

int SignalWatch::signal() const noexcept {
  return g_signal.load();
}

int SignalWatch::exit_code() const noexcept {
  const int s = g_signal.load();
  return s != 0 ? 128 + s : 128 + SIGINT;
}

const char* signal_name(int signal) noexcept {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

}  // namespace frontpack_tool
