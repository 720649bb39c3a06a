#include "mesh/io/mapped_file.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <mutex>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mesh/input_error.hpp"

namespace umbra {
namespace {

// The live mappings the SIGBUS handler may mend: lock-free, as a signal
// handler may read them at any moment. More files than this at once (a
// batch runs one per core) are mapped without the guard.
struct GuardedMapping {
  std::atomic<const char*> begin{nullptr};
  std::atomic<size_t> size{0};
  std::atomic<bool> cut{false};
};
constexpr int kSlots = 256;
GuardedMapping g_slots[kSlots];
size_t g_page_size = 4096;
struct sigaction g_previous {};

void on_bus_error(int signal, siginfo_t* info, void* context) {
  const char* at = static_cast<const char*>(info->si_addr);
  for (GuardedMapping& m : g_slots) {
    const char* begin = m.begin.load();
    if (!begin || at < begin || at >= begin + m.size.load()) continue;
    // mmap is a plain system call on Linux, safe here: a page of zeros over
    // the one the file lost, so that the faulting read goes on.
    void* page = reinterpret_cast<void*>(reinterpret_cast<uintptr_t>(at) & ~uintptr_t(g_page_size - 1));
    if (::mmap(page, g_page_size, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) != MAP_FAILED) {
      m.cut.store(true);
      return;
    }
  }
  // Not a file of ours: as it would have been without us.
  if ((g_previous.sa_flags & SA_SIGINFO) && g_previous.sa_sigaction) return g_previous.sa_sigaction(signal, info, context);
  if (g_previous.sa_handler != SIG_DFL && g_previous.sa_handler != SIG_IGN) return g_previous.sa_handler(signal);
  ::signal(SIGBUS, SIG_DFL);
  ::raise(SIGBUS);
}

void install_handler() {
  static std::once_flag once;
  std::call_once(once, [] {
    g_page_size = size_t(::sysconf(_SC_PAGESIZE));
    struct sigaction action {};
    action.sa_sigaction = on_bus_error;
    action.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGBUS, &action, &g_previous);
  });
}

int guard(const char* data, size_t size) {
  install_handler();
  for (int k = 0; k < kSlots; ++k) {
    const char* expected = nullptr;
    if (g_slots[k].begin.compare_exchange_strong(expected, data)) {
      g_slots[k].cut.store(false);
      g_slots[k].size.store(size);
      return k;
    }
  }
  return -1;
}

}  // namespace

std::string non_regular_kind(unsigned mode) {
  return S_ISDIR(mode) ? "a folder" : S_ISFIFO(mode) ? "a FIFO" : S_ISCHR(mode) ? "a character device"
         : S_ISBLK(mode) ? "a block device" : S_ISSOCK(mode) ? "a socket" : "not a plain file";
}

MappedFile::MappedFile(const std::string& path) {
  // Without O_NONBLOCK, opening a FIFO waits for a writer that may never come.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError({path, 0, 0}, std::string("cannot open: ") + std::strerror(errno), InputProblem::kUnreadable);
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    const bool folder = S_ISDIR(info.st_mode);
    ::close(fd);
    throw InputError({path, 0, 0}, folder ? "is a folder, not a mesh file" : "is not a regular file (" + non_regular_kind(info.st_mode) + ")",
                     InputProblem::kUnreadable);
  }
  size_ = size_t(info.st_size);
  if (size_ > 0) {
    void* mapped = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
    if (mapped == MAP_FAILED) {
      const int error = errno;
      ::close(fd);
      throw InputError({path, 0, 0}, std::string("cannot read the file: ") + std::strerror(error), InputProblem::kUnreadable);
    }
    ::madvise(mapped, size_, MADV_SEQUENTIAL);  // readers go front to back: read ahead, drop behind
    data_ = static_cast<const char*>(mapped);
    slot_ = guard(data_, size_);
  }
  ::close(fd);  // the mapping keeps the file
}

MappedFile::~MappedFile() {
  if (slot_ >= 0) {
    g_slots[slot_].size.store(0);
    g_slots[slot_].begin.store(nullptr);
  }
  if (data_) ::munmap(const_cast<char*>(data_), size_);
}

bool MappedFile::cut_short() const { return slot_ >= 0 && g_slots[slot_].cut.load(); }

}  // namespace umbra
