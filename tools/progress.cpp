#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frontpack_tool {

namespace {

// On a terminal, nothing is drawn before the run is half a second old: short runs print their
// summary only. A log (--progress) gets every phase.
constexpr double kQuietStart = 0.5;
constexpr double kTerminalEvery = 0.1;
constexpr double kLogEvery = 5.0;

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

ProgressLine::Mode ProgressLine::mode_for(bool shown, bool forced) {
  if (!shown) {
    return Mode::off;
  }
  if (::isatty(STDERR_FILENO) == 1) {
    return Mode::terminal;
  }
  return forced ? Mode::log : Mode::off;
}

ProgressLine::ProgressLine(Mode mode) : mode_(mode) {}

ProgressLine::~ProgressLine() {
  if (spinner_.joinable()) {
    spinner_.request_stop();
    spinner_.join();
  }
  clear();
}

void ProgressLine::draw(const std::string& text) {
  if (mode_ == Mode::terminal) {
    std::fputs(("\r" + text + "\033[K").c_str(), stderr);
    shown_ = true;
  } else if (mode_ == Mode::log) {
    std::fputs(("progress: " + text + "\n").c_str(), stderr);
  }
  std::fflush(stderr);
}

void ProgressLine::update(const frontpack::Progress& p) {
  if (mode_ == Mode::off) {
    return;
  }
  if (p.phase == frontpack::Phase::jam) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const double t = seconds(start_);
    if (t - last_ < (mode_ == Mode::terminal ? kTerminalEvery : kLogEvery)) {
      return;
    }
    last_ = t;
    char text[160];
    std::snprintf(text, sizeof text, "jamming: %zu disks, about %.0f%% of the rounds", p.disks, 100 * p.fraction);
    draw(text);
    return;
  }
  if (p.phase == frontpack::Phase::certify) {
    if (p.fraction < 1.0) {
      phase("certifying " + std::to_string(p.disks) + " disks (exact containment and overlap)");
    }
    return;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  const double t = seconds(start_);
  const bool end = p.fraction >= 1.0;
  const double every = mode_ == Mode::terminal ? kTerminalEvery : kLogEvery;
  if ((mode_ == Mode::terminal && t < kQuietStart) || (t - last_ < every && !end)) {
    return;
  }
  if (end && mode_ == Mode::terminal && !shown_) {
    return;  // a run that ends within the quiet start shows no bar
  }
  last_ = t;
  const double f = std::clamp(p.fraction, 0.0, 1.0);
  std::string text = "generating ";
  if (mode_ == Mode::terminal) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(f * kWidth);
    text.append("[")
        .append(static_cast<std::size_t>(filled), '#')
        .append(static_cast<std::size_t>(kWidth - filled), '.');
    text.append("] ");
  }
  char tail[160];
  const double rate = static_cast<double>(p.disks) / t;
  const double eta = f > 0.01 && !end ? t * (1 - f) / f : NAN;
  if (std::isfinite(eta)) {
    std::snprintf(tail, sizeof tail, "%3.0f%% of area  %zu disks  %.3g disks/s  ETA %.0f s", 100 * f, p.disks, rate,
                  eta);
  } else {
    std::snprintf(tail, sizeof tail, "%3.0f%% of area  %zu disks  %.3g disks/s", 100 * f, p.disks, rate);
  }
  draw(text + tail);
}

void ProgressLine::phase(const std::string& name) {
  if (mode_ == Mode::off) {
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    phase_ = name;
    phase_start_ = Clock::now();
    if (mode_ == Mode::log) {
      draw(name);
    }
  }
  if (mode_ == Mode::terminal && !spinner_.joinable()) {
    spinner_ = std::jthread([this](const std::stop_token& stop) { spin(stop); });
  }
}

void ProgressLine::spin(const std::stop_token& stop) {
  static constexpr const char* kFrames = "|/-\\";
  std::size_t frame = 0;
  while (!stop.stop_requested()) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!phase_.empty() && seconds(start_) >= kQuietStart) {
        char tail[64];
        std::snprintf(tail, sizeof tail, " %c %.1f s", kFrames[frame++ % 4], seconds(phase_start_));
        draw(phase_ + tail);
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

void ProgressLine::clear() {
  const std::lock_guard<std::mutex> lock(mutex_);
  phase_.clear();
  if (shown_) {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    shown_ = false;
  }
}

}  // namespace frontpack_tool
