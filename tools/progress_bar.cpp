#include "tools/progress_bar.hpp"

#include <algorithm>
#include <iostream>

#include <unistd.h>

namespace umbra {

ProgressBar::ProgressBar(size_t total)
    : total_(total), terminal_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(size_t done, const std::string& what) {
  done_ = done;
  if (!terminal_ || std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
  constexpr size_t kWidth = 30;
  const size_t filled = kWidth * std::min(done, total_) / std::max<size_t>(1, total_);
  std::cerr << "\r\033[K[" << std::string(filled, '#') << std::string(kWidth - filled, ' ') << "] " << done << "/"
            << total_ << " " << what.substr(0, 60) << std::flush;
  drawn_ = true;
}

void ProgressBar::clear() {
  if (!drawn_) return;
  std::cerr << "\r\033[K" << std::flush;
  drawn_ = false;
}

}  // namespace umbra
