#include "image/partial_file.hpp"

#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace umbra {
namespace {

// The paths to remove, for the signal handler: a handler may call little
// more than unlink(2) and rmdir(2), so the list is fixed slots of plain
// characters, each published by its flag once its name is whole. A global,
// as nothing else reaches a signal handler. Paths past the slots' number
// (more pictures drawn at once than any machine has cores) go unlisted.
constexpr int kSlots = 256;
constexpr size_t kLongestPath = 4096;
struct Slot {
  std::atomic<bool> used{false};
  std::atomic<bool> listed{false};
  bool folder = false;
  char path[kLongestPath];
};
Slot slots[kSlots];

int list(const std::string& path, bool folder) {
  if (path.size() >= kLongestPath) return -1;
  for (int s = 0; s < kSlots; ++s) {
    bool free = false;
    if (!slots[s].used.compare_exchange_strong(free, true)) continue;
    std::memcpy(slots[s].path, path.c_str(), path.size() + 1);
    slots[s].folder = folder;
    slots[s].listed.store(true);
    return s;
  }
  return -1;
}

// The process's umask, read without changing it (umask(2) can only set it,
// which would race with threads creating files): Linux's /proc/self/status
// says it; failing that, 022, the usual one.
mode_t current_umask() {
  std::FILE* status = std::fopen("/proc/self/status", "r");
  unsigned mask = 022;
  if (status) {
    char line[256];
    while (std::fgets(line, sizeof line, status))
      if (std::sscanf(line, "Umask: %o", &mask) == 1) break;
    std::fclose(status);
  }
  return mode_t(mask);
}

void remove_listed_and_die(int signal_number) {
  for (Slot& slot : slots)
    if (slot.listed.load() && !slot.folder) ::unlink(slot.path);
  for (Slot& slot : slots)
    if (slot.listed.load() && slot.folder) ::rmdir(slot.path);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

// A temporary file's name: `start`, six random characters, `end`.
struct TemporaryName {
  std::string start, end;
};

// The final name, cut short where the random part and the ending would
// take it past the longest name the folder allows (255 bytes on Linux's
// file systems), so that a legal final name always gets a temporary one;
// then ".XXXXXX.partial", and the extension where `ending` keeps it.
TemporaryName temporary_name(const std::string& path, PartialFile::Ending ending) {
  const size_t slash = path.rfind('/'), dot = path.rfind('.');
  const std::string extension = ending == PartialFile::Ending::kKeepExtension && dot != std::string::npos &&
                                        (slash == std::string::npos || dot > slash)
                                    ? path.substr(dot)
                                    : "";
  const std::string end = ".partial" + extension;
  const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::string base = path.substr(folder.size());
  long longest = ::pathconf(folder.empty() ? "." : folder.c_str(), _PC_NAME_MAX);
  if (longest <= 0) longest = 255;
  const size_t added = 7 + end.size();  // ".XXXXXX" and the end
  if (base.size() + added > size_t(longest)) base.resize(size_t(longest) > added ? size_t(longest) - added : 1);
  return {folder + base + ".", end};
}

}  // namespace

void remove_abandoned_temporaries(const std::string& path, PartialFile::Ending ending) {
  const TemporaryName parts = temporary_name(path, ending);
  const std::filesystem::path start(parts.start);
  const std::string first = start.filename().string();
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(start.parent_path().empty() ? "." : start.parent_path(), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() == first.size() + 6 + parts.end.size() && name.compare(0, first.size(), first) == 0 &&
        name.compare(name.size() - parts.end.size(), parts.end.size(), parts.end) == 0 && entry.is_regular_file(ec))
      std::filesystem::remove(entry.path(), ec);
  }
}

void remove_abandoned_temporaries_in(const std::string& folder) {
  std::error_code ec;
  const std::string end = ".partial";
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    // NAME.XXXXXX.partial, as temporary_name makes them.
    const std::string name = entry.path().filename().string();
    const size_t size = name.size();
    if (size > end.size() + 7 && name.compare(size - end.size(), end.size(), end) == 0 && name[size - end.size() - 7] == '.' &&
        entry.is_regular_file(ec))
      std::filesystem::remove(entry.path(), ec);
  }
}

RemovedOnSignals::RemovedOnSignals(const std::string& path, Kind kind) : slot_(list(path, kind == Kind::kFolder)) {}

void RemovedOnSignals::release() {
  if (slot_ < 0) return;
  slots[slot_].listed.store(false);
  slots[slot_].used.store(false);
  slot_ = -1;
}

PartialFile::PartialFile(const std::string& path, const std::string& what, Ending ending) : path_(path), what_(what) {
  // What is there already decides: a FIFO or a character device (-o
  // /dev/null) is written in place, as renaming over it would replace the
  // device itself; a folder or a block device takes no file.
  struct stat there {};
  if (::stat(path.c_str(), &there) == 0 && !S_ISREG(there.st_mode)) {
    if (S_ISFIFO(there.st_mode) || S_ISCHR(there.st_mode)) {
      temporary_ = path;
      in_place_ = true;
      return;
    }
    throw std::runtime_error(path + ": cannot write " + what + ": it is " +
                             (S_ISDIR(there.st_mode) ? "a folder" : S_ISBLK(there.st_mode) ? "a block device" : "not a file"));
  }
  const TemporaryName parts = temporary_name(path, ending);
  const std::string pattern = parts.start + "XXXXXX" + parts.end;
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemps(name.data(), int(parts.end.size()));
  if (fd < 0) throw std::runtime_error(path + ": cannot write " + what + ": " + std::strerror(errno));
  // mkstemps makes it 0600; once renamed it is a file like any other.
  ::fchmod(fd, 0666 & ~current_umask());
  ::close(fd);
  temporary_ = name.data();
  listed_.emplace(temporary_);
}

PartialFile::~PartialFile() {
  if (!committed_ && !in_place_) std::remove(temporary_.c_str());
}

void PartialFile::commit() {
  if (in_place_) return;
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error(path_ + ": cannot write " + what_ + ": " + std::strerror(errno));
  committed_ = true;
  listed_.reset();
}

void remove_partial_files_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_listed_and_die;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal_number, &action, nullptr);
}

}  // namespace umbra
