#pragma once
// Frames handed to an animation's writer on a thread of its own, so that
// one is encoded while the next is drawn (umbra render --turntable) or
// while the window goes on (umbra view's recording); at most two wait.

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "image/animation_file.hpp"
#include "image/image.hpp"

namespace umbra {

class EncodingThread {
 public:
  explicit EncodingThread(AnimationWriter& writer);
  // Stops without finishing the file, whose writer's caller removes it.
  ~EncodingThread();
  EncodingThread(const EncodingThread&) = delete;
  EncodingThread& operator=(const EncodingThread&) = delete;

  // Waits while two frames wait; throws what the writer threw, once it has.
  void add(Image frame);
  // Every frame written and the file finished; throws what the writer threw.
  void finish();

 private:
  void stop(bool finish);
  void run();

  AnimationWriter& writer_;
  std::mutex mutex_;
  std::condition_variable ready_, space_;
  std::deque<Image> waiting_;
  bool closed_ = false, finish_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: it starts once the rest is made
};

}  // namespace umbra
