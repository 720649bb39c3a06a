#pragma once
// Runs of one job per file in worker processes, so that a file that hangs,
// crashes or runs out of memory costs only its own result: the folder runs
// of `umbra render` (and of `umbra check --timeout`) over corpora of
// downloaded files, some of them broken or hostile. A worker does one job at
// a time and keeps what it made for the next (a GL context); one that
// crashes or runs past its time is replaced, and each is replaced after 256
// jobs, so that nothing a library leaks piles up.

#include <cstddef>
#include <functional>
#include <string>

namespace umbra {

struct IsolatedResult {
  enum class Ending {
    kFinished,  // the job returned: `output` is what it returned
    kTimedOut,  // stopped (SIGTERM, then SIGKILL) after the time allowed
    kKilled,    // ended by a signal: a crash (SIGSEGV, SIGABRT) or the kernel's OOM killer (SIGKILL)
  };
  Ending ending = Ending::kFinished;
  int signal = 0;       // kKilled: the signal that ended it
  int exit_status = 0;  // kFinished: the process's (0 when the job returned)
  std::string output;
  double seconds = 0.0;
};

// "SIGINT", "SIGTERM": a signal's name as kill(1) and the shell say it.
std::string signal_name(int signal_number);

// What `result` says of a job that did not finish: "timed out after 10 s",
// "crashed (SIGSEGV)", "killed (SIGKILL: out of memory?)"; "" for one that did.
std::string unfinished_phrase(const IsolatedResult& result, double timeout_s);

// Runs `job(i)` for each i in [0, count) in forked worker processes, at
// most `jobs` at a time, each job stopped (its worker killed) after
// `timeout_s` seconds (0: no limit). `done(i, result)` is called here, in
// this process, as each ends, in the order they end. Each worker lets TBB
// use its share of the cores (cores / jobs, at least one). Workers end with
// this process; each has only the thread that forked it, so a job must touch no
// state of this process's other threads (a progress bar's), and must not
// throw. What a job keeps in this process's memory (captured by reference)
// is its worker's own copy, kept from one job to its worker's next.
//
// A job past its time, and every worker when this process is asked to stop,
// is stopped with SIGTERM, whose handler removes the files the worker was
// writing, and killed (SIGKILL) if it has not ended two seconds later.
// SIGINT, SIGTERM or SIGHUP to this process stops the run: its workers are
// stopped and waited for, the jobs under way are not reported, and the
// signal's number is returned (0 once every job has been reported), so
// that the caller can say what was done before it ends.
int run_isolated(size_t count, size_t jobs, double timeout_s, const std::function<std::string(size_t)>& job,
                 const std::function<void(size_t, const IsolatedResult&)>& done);

}  // namespace umbra
