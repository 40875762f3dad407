// The progress line of long runs: one line on stderr, redrawn in place on a terminal, naming the
// phase (generating, certifying, measuring, writing) and, while generating, the share of the area
// filled with an ETA. Phases without a measure of progress show a spinner and their time, redrawn
// by a thread of the line's own, so that the line never freezes. With --progress and stderr not a
// terminal (a log), one line per phase, and while generating one every 5 s and one at 100%.
#pragma once

#include <chrono>
#include <mutex>
#include <string>
#include <thread>

#include "frontpack/fill.hpp"

namespace frontpack_tool {

class ProgressLine {
 public:
  enum class Mode { off, terminal, log };
  /// `shown`: false for --quiet; `forced`: --progress. Off, or on a terminal, or as log lines.
  [[nodiscard]] static Mode mode_for(bool shown, bool forced);

  explicit ProgressLine(Mode mode);
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine();

  /// From the generator's callback: the bar while generating; the certification phase once the
  /// library reports it.
  void update(const frontpack::Progress& p);
  /// A phase without a measure of progress (e.g. "writing packing.csv"): a spinner and its time.
  void phase(const std::string& name);
  /// Removes the line (on a terminal) before the summary is printed.
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  void draw(const std::string& text);  // the caller holds mutex_
  void spin(const std::stop_token& stop);

  Mode mode_;
  Clock::time_point start_ = Clock::now();
  std::mutex mutex_;
  bool shown_ = false;  // a line is on the terminal
  double last_ = -1e9;  // when the bar or a log line was last drawn (seconds since start_)
  std::string phase_;   // the spinner's phase ("" while generating or done)
  Clock::time_point phase_start_ = Clock::now();
  std::jthread spinner_;  // started with the first phase()
};

}  // namespace frontpack_tool
