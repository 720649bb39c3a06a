#pragma once
// A test fixture that runs the umbra executable in a scratch folder and keeps
// its exit status, stdout and stderr.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/scratch_folder.hpp"

namespace umbra::test {

namespace fs = std::filesystem;

struct CommandResult {
  int status = 0;
  std::string out, err;
};

class CommandTest : public ScratchFolder {
 protected:
  std::string path(const std::string& name) const { return (folder_ / name).string(); }

  // Runs `umbra ARGS`, after `prefix` (such as "xvfb-run -a ") when given;
  // `executable` is another build of umbra (a test build's).
  CommandResult run(const std::string& args, const std::string& prefix = "", const std::string& executable = UMBRA_EXECUTABLE) const {
    const std::string command = prefix + executable + " " + args + " >" + path("out.txt") + " 2>" + path("err.txt");
    CommandResult r;
    const int raw = std::system(command.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = read(path("out.txt"));
    r.err = read(path("err.txt"));
    return r;
  }

  // `text` as one word of a shell command: file names with quotes, line
  // breaks or backquotes pass through run() as they are.
  static std::string shell_quoted(const std::string& text) {
    std::string q = "'";
    for (const char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  }

  static std::string read(const std::string& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
};

}  // namespace umbra::test
