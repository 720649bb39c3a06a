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
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace umbra {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  pid_t pid = -1;
  int from_job = -1;  // the read end of the job's pipe, -1 once it is closed
  size_t index = 0;
  Clock::time_point start;
  std::string output;
};

// Writes all of `bytes` to `fd`, across short writes.
void write_all(int fd, const std::string& bytes) {
  for (size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += size_t(n);
  }
}

// The job's process: runs it, hands its output to the parent and ends
// without the parent's exit handlers (its GL libraries, its streams).
[[noreturn]] void run_job(size_t index, int to_parent, pid_t parent, const std::function<std::string(size_t)>& job) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // the parent gone, nobody reads the result
  if (::getppid() != parent) ::_exit(1);
  const std::string output = job(index);
  write_all(to_parent, output);
  std::cout.flush(), std::cerr.flush();
  ::_exit(0);
}

Running start(size_t index, const std::function<std::string(size_t)>& job) {
  int pipe_ends[2];
  if (::pipe2(pipe_ends, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  const pid_t parent = ::getpid();
  std::cout.flush(), std::cerr.flush();  // or the child would write the parent's buffered text again
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipe_ends[0]), ::close(pipe_ends[1]);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(pipe_ends[0]);
    run_job(index, pipe_ends[1], parent, job);
  }
  ::close(pipe_ends[1]);
  return Running{pid, pipe_ends[0], index, Clock::now(), {}};
}

IsolatedResult reap(Running& r, bool timed_out) {
  if (timed_out) ::kill(r.pid, SIGKILL);
  if (r.from_job >= 0) ::close(r.from_job), r.from_job = -1;
  int status = 0;
  while (::waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
  }
  IsolatedResult result;
  result.seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
  if (timed_out) {
    result.ending = IsolatedResult::Ending::kTimedOut;
  } else if (WIFSIGNALED(status)) {
    result.ending = IsolatedResult::Ending::kKilled;
    result.signal = WTERMSIG(status);
  } else {
    result.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 0;
    result.output = std::move(r.output);
  }
  return result;
}

}  // namespace

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
  const char* name = sigabbrev_np(result.signal);
  const std::string signal = name ? std::string("SIG") + name : "signal " + std::to_string(result.signal);
  if (result.signal == SIGKILL) return "killed (" + signal + ": out of memory?)";
  return "crashed (" + signal + ")";
}

void run_isolated(size_t count, size_t jobs, double timeout_s, const std::function<std::string(size_t)>& job,
                  const std::function<void(size_t, const IsolatedResult&)>& done) {
  std::vector<Running> running;
  size_t next = 0;
  while (next < count || !running.empty()) {
    while (next < count && running.size() < std::max<size_t>(jobs, 1)) running.push_back(start(next++, job));
    // Wait for output, an end, or the first time limit.
    int wait_ms = -1;
    if (timeout_s > 0.0) {
      double soonest = timeout_s;
      for (const Running& r : running) soonest = std::min(soonest, timeout_s - std::chrono::duration<double>(Clock::now() - r.start).count());
      wait_ms = int(std::ceil(std::max(soonest, 0.0) * 1000.0));
    }
    std::vector<pollfd> fds;
    for (const Running& r : running) fds.push_back({r.from_job, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), wait_ms) < 0 && errno != EINTR)
      throw std::runtime_error(std::string("cannot wait for the jobs: ") + std::strerror(errno));
    for (size_t k = 0; k < running.size();) {
      Running& r = running[k];
      bool ended = false, timed_out = false;
      if (fds[k].revents & (POLLIN | POLLHUP | POLLERR)) {
        char buffer[65536];
        const ssize_t n = ::read(r.from_job, buffer, sizeof buffer);
        if (n > 0) r.output.append(buffer, size_t(n));
        else if (n == 0 || errno != EINTR) ended = true;
      }
      if (!ended && timeout_s > 0.0 && std::chrono::duration<double>(Clock::now() - r.start).count() >= timeout_s)
        ended = timed_out = true;
      if (!ended) {
        ++k;
        continue;
      }
      const size_t index = r.index;
      const IsolatedResult result = reap(r, timed_out);
      running.erase(running.begin() + std::ptrdiff_t(k));
      fds.erase(fds.begin() + std::ptrdiff_t(k));
      done(index, result);
    }
  }
}

}  // namespace umbra
