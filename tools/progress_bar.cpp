#include "tools/progress_bar.hpp"

#include <algorithm>
#include <iostream>

#include <unistd.h>

namespace umbra {

ProgressBar::ProgressBar(size_t total)
    : total_(total), terminal_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {
  if (!terminal_) return;
  ticker_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stopping_; }))
      if (!hidden_ && std::chrono::steady_clock::now() - start_ >= std::chrono::seconds(1)) draw_locked();
  });
}

ProgressBar::~ProgressBar() {
  if (!terminal_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    erase_locked();
  }
  stop_.notify_one();
  ticker_.join();
}

void ProgressBar::update(size_t done, const std::string& what) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = done;
  what_ = what;
  hidden_ = false;
}

void ProgressBar::step(const std::string& what) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  what_ = what;
  hidden_ = false;
}

void ProgressBar::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  hidden_ = true;
  erase_locked();
}

void ProgressBar::draw_locked() {
  constexpr size_t kWidth = 30;
  const size_t filled = kWidth * std::min(done_, total_) / std::max<size_t>(1, total_);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::cerr << "\r\033[K[" << std::string(filled, '#') << std::string(kWidth - filled, ' ') << "] " << done_ << "/"
            << total_ << " " << int(seconds) << " s " << what_.substr(0, 60) << std::flush;
  drawn_ = true;
}

void ProgressBar::erase_locked() {
  if (!drawn_) return;
  std::cerr << "\r\033[K" << std::flush;
  drawn_ = false;
}

}  // namespace umbra
