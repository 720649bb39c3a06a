#include "tools/isolated_runs.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <tbb/global_control.h>

#include "image/partial_file.hpp"

namespace umbra {
namespace {

using Clock = std::chrono::steady_clock;

// A worker is replaced after this many jobs, so that whatever a library
// leaks or scatters over a long run (a GL driver's caches, say) goes with it.
constexpr size_t kJobsPerWorker = 256;

// A worker process: takes job indices on one pipe and answers each with the
// job's output, its length first, on another.
struct Worker {
  pid_t pid = -1;
  int to_worker = -1;    // this process's end of the index pipe
  int from_worker = -1;  // this process's end of the result pipe
  size_t jobs_done = 0;
  std::optional<size_t> index;  // the job under way
  Clock::time_point start;
  std::string received;  // the result's bytes so far
};

bool write_all(int fd, const void* bytes, size_t size) {
  const char* at = static_cast<const char*>(bytes);
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, at + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += size_t(n);
  }
  return true;
}

bool read_all(int fd, void* bytes, size_t size) {
  char* at = static_cast<char*>(bytes);
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::read(fd, at + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += size_t(n);
  }
  return true;
}

// The worker's life: jobs until the index pipe closes, then an end without
// this process's exit handlers (its GL libraries, its streams). The `jobs`
// workers share the cores: each takes its part for its own threads.
[[noreturn]] void work(int indices, int results, pid_t parent, size_t jobs, const std::function<std::string(size_t)>& job) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // the parent gone, nobody reads the results
  if (::getppid() != parent) ::_exit(1);
  const size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, std::max<size_t>(1, cores / jobs));
  for (uint64_t index = 0; read_all(indices, &index, sizeof index);) {
    const std::string output = job(size_t(index));
    const uint64_t size = output.size();
    if (!write_all(results, &size, sizeof size) || !write_all(results, output.data(), output.size())) break;
  }
  std::cout.flush(), std::cerr.flush();
  ::_exit(0);
}

Worker start_worker(const std::vector<Worker>& others, size_t jobs, const std::function<std::string(size_t)>& job) {
  int indices[2], results[2];
  if (::pipe(indices) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  if (::pipe(results) != 0) {
    ::close(indices[0]), ::close(indices[1]);
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  const pid_t parent = ::getpid();
  std::cout.flush(), std::cerr.flush();  // or the worker would write this process's buffered text again
  const pid_t pid = ::fork();
  if (pid < 0) {
    for (const int fd : {indices[0], indices[1], results[0], results[1]}) ::close(fd);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Only its own pipes: another worker's ends held here would keep that
    // worker from seeing its index pipe close.
    for (const Worker& w : others)
      for (const int fd : {w.to_worker, w.from_worker})
        if (fd >= 0) ::close(fd);
    ::close(indices[1]), ::close(results[0]);
    remove_partial_files_on_signals();  // not the parent's StopOnSignals: a worker ends, removing its files
    work(indices[0], results[1], parent, jobs, job);
  }
  ::close(indices[0]), ::close(results[1]);
  Worker w;
  w.pid = pid, w.to_worker = indices[1], w.from_worker = results[0];
  return w;
}

// How long a worker told to stop (SIGTERM) has to remove its temporary
// files before it is killed (SIGKILL).
constexpr auto kGraceToStop = std::chrono::seconds(2);

// Ends `w`, waits for it, and says how it ended. Where `stop`, it is told
// to with SIGTERM, whose handler removes the files it was writing
// (remove_partial_files_on_signals), and killed if it has not ended in
// kGraceToStop; else its index pipe closes and it ends by itself.
int stop_worker(Worker& w, bool stop) {
  for (int* fd : {&w.to_worker, &w.from_worker})
    if (*fd >= 0) ::close(*fd), *fd = -1;
  int status = 0;
  if (stop) {
    ::kill(w.pid, SIGTERM);
    for (const auto deadline = Clock::now() + kGraceToStop; Clock::now() < deadline;) {
      const pid_t ended = ::waitpid(w.pid, &status, WNOHANG);
      if (ended == w.pid || (ended < 0 && errno != EINTR)) return status;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::kill(w.pid, SIGKILL);
  }
  while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

// The signal that asked this process to stop, while run_isolated runs.
volatile std::sig_atomic_t stop_asked = 0;

// SIGINT, SIGTERM and SIGHUP, while the workers run, ask the run to stop
// (stop_asked), so that it stops its workers and waits for them, each
// removing its own temporary files, before the caller says what was done;
// the handlers before are put back after.
class StopOnSignals {
 public:
  StopOnSignals() {
    stop_asked = 0;
    struct sigaction action {};
    action.sa_handler = [](int signal_number) { stop_asked = signal_number; };
    sigemptyset(&action.sa_mask);  // no SA_RESTART: the wait for results ends at once
    for (size_t k = 0; k < std::size(kSignals); ++k) ::sigaction(kSignals[k], &action, &previous_[k]);
  }
  ~StopOnSignals() {
    for (size_t k = 0; k < std::size(kSignals); ++k) ::sigaction(kSignals[k], &previous_[k], nullptr);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  static constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction previous_[std::size(kSignals)] {};
};

// The result `w` has received whole, if it has: its output, less its length.
std::optional<std::string> whole_result(const Worker& w) {
  uint64_t size = 0;
  if (w.received.size() < sizeof size) return std::nullopt;
  std::memcpy(&size, w.received.data(), sizeof size);
  if (w.received.size() < sizeof size + size) return std::nullopt;
  return w.received.substr(sizeof size, size_t(size));
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The result of `w`'s job, which returned `output`.
IsolatedResult returned(const Worker& w, std::string output) {
  IsolatedResult result;
  result.seconds = seconds_since(w.start);
  result.output = std::move(output);
  return result;
}

// SIGPIPE ignored while the workers run: a worker that died with an index on
// its way is reported as such, not taken for this process's own death.
class IgnoredSigpipe {
 public:
  IgnoredSigpipe() { previous_ = ::signal(SIGPIPE, SIG_IGN); }
  ~IgnoredSigpipe() { ::signal(SIGPIPE, previous_); }

 private:
  sighandler_t previous_;
};

}  // namespace

std::string signal_name(int signal_number) {
  const char* name = sigabbrev_np(signal_number);
  return name ? std::string("SIG") + name : "signal " + std::to_string(signal_number);
}

std::string unfinished_phrase(const IsolatedResult& result, double timeout_s) {
  switch (result.ending) {
    case IsolatedResult::Ending::kFinished: return "";
    case IsolatedResult::Ending::kTimedOut: {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", timeout_s);
      return std::string("timed out after ") + seconds + " s (--timeout)";
    }
    case IsolatedResult::Ending::kKilled: break;
  }
  const std::string signal = signal_name(result.signal);
  if (result.signal == SIGKILL) return "killed (" + signal + ": out of memory?)";
  return "crashed (" + signal + ")";
}

int run_isolated(size_t count, size_t jobs, double timeout_s, const std::function<std::string(size_t)>& job,
                 const std::function<void(size_t, const IsolatedResult&)>& done) {
  const IgnoredSigpipe ignored;
  const StopOnSignals stop_on_signals;
  std::vector<Worker> workers;
  size_t next = 0, finished = 0;
  // A worker ended while on a job: the job's result is how it ended.
  const auto lost = [&](Worker& w, bool timed_out) {
    const size_t index = *w.index;
    IsolatedResult result;
    result.seconds = seconds_since(w.start);
    const int status = stop_worker(w, timed_out);
    if (timed_out) {
      result.ending = IsolatedResult::Ending::kTimedOut;
    } else if (WIFSIGNALED(status)) {
      result.ending = IsolatedResult::Ending::kKilled;
      result.signal = WTERMSIG(status);
    } else {
      result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 0;
    }
    ++finished;
    done(index, result);
  };
  while (finished < count) {
    if (stop_asked) {
      // A result already sent is reported (its files are written); the jobs
      // still under way end unfinished, and are not.
      for (Worker& w : workers) {
        if (w.pid < 0 || !w.index) continue;
        char buffer[65536];
        for (pollfd fd{w.from_worker, POLLIN, 0}; !whole_result(w) && ::poll(&fd, 1, 0) > 0 && (fd.revents & POLLIN);) {
          const ssize_t n = ::read(w.from_worker, buffer, sizeof buffer);
          if (n <= 0) break;
          w.received.append(buffer, size_t(n));
        }
        if (const std::optional<std::string> output = whole_result(w)) {
          done(*w.index, returned(w, *output));
        }
      }
      for (Worker& w : workers)
        if (w.pid >= 0) stop_worker(w, true);
      return stop_asked;
    }
    // Every job under way, as far as the workers go: idle ones take the next.
    workers.erase(std::remove_if(workers.begin(), workers.end(), [](const Worker& w) { return w.pid < 0; }), workers.end());
    for (Worker& w : workers) {
      if (w.index || next >= count) continue;
      const uint64_t index = next;
      if (!write_all(w.to_worker, &index, sizeof index)) {  // it died idle: replaced below
        stop_worker(w, true), w.pid = -1;
        continue;
      }
      w.index = next++, w.start = Clock::now(), w.received.clear();
    }
    workers.erase(std::remove_if(workers.begin(), workers.end(), [](const Worker& w) { return w.pid < 0; }), workers.end());
    if (next < count && workers.size() < std::min(std::max<size_t>(jobs, 1), count - finished)) {
      workers.push_back(start_worker(workers, std::max<size_t>(jobs, 1), job));
      continue;
    }
    // Wait for results, an end, or the first time limit.
    int wait_ms = -1;
    if (timeout_s > 0.0) {
      double soonest = timeout_s;
      for (const Worker& w : workers)
        if (w.index) soonest = std::min(soonest, timeout_s - seconds_since(w.start));
      wait_ms = int(std::ceil(std::max(soonest, 0.0) * 1000.0));
    }
    std::vector<pollfd> fds;
    for (const Worker& w : workers) fds.push_back({w.index ? w.from_worker : -1, POLLIN, 0});  // -1: not polled
    if (::poll(fds.data(), fds.size(), wait_ms) < 0 && errno != EINTR)
      throw std::runtime_error(std::string("cannot wait for the jobs: ") + std::strerror(errno));
    // Ctrl-C reaches the workers with this process (one process group): a
    // worker it ended is stopped, not crashed. The signal is taken by the
    // time the wait returns, since one kill(2) sent both.
    if (stop_asked) continue;
    for (size_t k = 0; k < workers.size(); ++k) {
      Worker& w = workers[k];
      if (!w.index) continue;
      if (fds[k].revents & (POLLIN | POLLHUP | POLLERR)) {
        char buffer[65536];
        const ssize_t n = ::read(w.from_worker, buffer, sizeof buffer);
        if (n > 0) {
          w.received.append(buffer, size_t(n));
        } else if (n == 0 || errno != EINTR) {
          lost(w, false);  // it ended before its result was whole
          w.pid = -1;
          continue;
        }
      }
      if (const std::optional<std::string> output = whole_result(w)) {
        const IsolatedResult result = returned(w, *output);
        const size_t index = *w.index;
        w.index.reset();
        if (++w.jobs_done >= kJobsPerWorker) stop_worker(w, false), w.pid = -1;
        ++finished;
        done(index, result);
      } else if (timeout_s > 0.0 && seconds_since(w.start) >= timeout_s) {
        lost(w, true);
        w.pid = -1;
      }
    }
  }
  for (Worker& w : workers)
    if (w.pid >= 0) stop_worker(w, false);  // its index pipe closed: it ends
  return 0;
}

}  // namespace umbra
