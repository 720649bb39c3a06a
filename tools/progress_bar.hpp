#pragma once
// A progress bar on stderr for work that takes a while: drawn only when
// stderr is a terminal and the work has run for over a second, so that
// quick commands, pipes and logs see nothing of it.

#include <chrono>
#include <cstddef>
#include <string>

namespace umbra {

class ProgressBar {
 public:
  explicit ProgressBar(size_t total);
  ~ProgressBar() { clear(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // `done` of the total finished, `what` under way.
  void update(size_t done, const std::string& what);
  // One more finished, `what` under way.
  void step(const std::string& what) { update(++done_, what); }
  // Removes the bar, before other output to the terminal; update() redraws it.
  void clear();

 private:
  size_t total_, done_ = 0;
  bool terminal_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace umbra
