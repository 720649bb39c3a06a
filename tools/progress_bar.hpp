#pragma once
// A progress bar on stderr for work that takes a while: drawn only when
// stderr is a terminal and the work has run for over a second, so that
// quick commands, pipes and logs see nothing of it. A thread redraws it
// every fifth of a second, so that one long step still shows.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

namespace umbra {

class ProgressBar {
 public:
  explicit ProgressBar(size_t total);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // `done` of the total finished, `what` under way.
  void update(size_t done, const std::string& what);
  // One more finished, `what` under way.
  void step(const std::string& what);
  // Removes the bar while the caller writes to the terminal; the next
  // update() or step() lets it be drawn again.
  void clear();

 private:
  void draw_locked();
  void erase_locked();

  const size_t total_;
  const bool terminal_;
  const std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false, hidden_ = false, drawn_ = false;
  size_t done_ = 0;
  std::string what_;
  std::thread ticker_;
};

}  // namespace umbra
