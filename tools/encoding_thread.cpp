#include "tools/encoding_thread.hpp"

namespace umbra {

EncodingThread::EncodingThread(AnimationWriter& writer) : writer_(writer), thread_([this] { run(); }) {}

EncodingThread::~EncodingThread() { stop(false); }

void EncodingThread::add(Image frame) {
  std::unique_lock<std::mutex> lock(mutex_);
  space_.wait(lock, [&] { return waiting_.size() < 2 || error_; });
  if (error_) std::rethrow_exception(error_);
  waiting_.push_back(std::move(frame));
  ready_.notify_one();
}

void EncodingThread::finish() {
  stop(true);
  if (error_) std::rethrow_exception(error_);
}

void EncodingThread::stop(bool finish) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (closed_) return;
    closed_ = true, finish_ = finish;
    ready_.notify_one();
  }
  if (thread_.joinable()) thread_.join();
}

void EncodingThread::run() {
  try {
    for (;;) {
      Image frame;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ready_.wait(lock, [&] { return !waiting_.empty() || closed_; });
        if (waiting_.empty()) break;
        frame = std::move(waiting_.front());
        waiting_.pop_front();
        space_.notify_one();
      }
      writer_.add(frame);
    }
    if (finish_) writer_.finish();  // else the run stopped: its file is left unfinished, and removed
  } catch (...) {
    const std::lock_guard<std::mutex> lock(mutex_);
    error_ = std::current_exception();
    space_.notify_one();
  }
}

}  // namespace umbra
