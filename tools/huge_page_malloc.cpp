#include "tools/huge_page_malloc.hpp"

#include <sys/auxv.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

namespace umbra {

namespace {

const char* const kTunable = "glibc.malloc.hugetlb=1";

std::optional<std::string> environment_variable(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::optional<std::string>(value) : std::nullopt;
}

// The kernel's mode is the bracketed word: "always [madvise] never".
std::string selected_mode(const std::string& modes) {
  const size_t open = modes.find('['), close = modes.find(']', open);
  return open == std::string::npos || close == std::string::npos ? "" : modes.substr(open + 1, close - open - 1);
}

}  // namespace

MallocEnvironment current_malloc_environment() {
  MallocEnvironment env;
  env.glibc_tunables = environment_variable("GLIBC_TUNABLES");
  env.ld_preload = environment_variable("LD_PRELOAD");
  std::ifstream modes("/sys/kernel/mm/transparent_hugepage/enabled");
  env.transparent_huge_pages.assign(std::istreambuf_iterator<char>(modes), {});
  // The kernel names an interpreter's base (AT_BASE) only when it started
  // the interpreter for the program; run as a program itself, the loader
  // has none, and umbra is no static executable.
  env.started_by_loader = getauxval(AT_BASE) == 0;
#if defined(__SANITIZE_ADDRESS__)
  env.sanitizer_allocator = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  env.sanitizer_allocator = true;
#endif
#endif
  return env;
}

// glibc 2.35 brought the tunable; other C libraries have none.
#if defined(__GLIBC__)
#if __GLIBC_PREREQ(2, 35)
#define UMBRA_HAS_HUGETLB_TUNABLE 1
#endif
#endif

std::optional<std::string> reason_not_to_restart(const MallocEnvironment& env) {
#if !defined(UMBRA_HAS_HUGETLB_TUNABLE)
  return "this C library has no glibc.malloc.hugetlb tunable";
#endif
  if (env.sanitizer_allocator) return "AddressSanitizer's allocator is in charge of memory";
  if (env.started_by_loader) return "umbra was started through the dynamic loader, which a restart would run instead";
  if (env.glibc_tunables) return "GLIBC_TUNABLES is set, and umbra leaves it as it is";
  if (env.ld_preload) return "LD_PRELOAD is set (a profiler or another malloc may be in charge)";
  const std::string mode = selected_mode(env.transparent_huge_pages);
  if (mode.empty()) return "this kernel offers no transparent huge pages";
  if (mode == "always") return "the kernel gives large blocks transparent huge pages unasked";
  if (mode != "madvise") return "the kernel's transparent huge pages are off (" + mode + ")";
  return std::nullopt;
}

std::string malloc_pages_description(const MallocEnvironment& env) {
  if (env.glibc_tunables && env.glibc_tunables->find(kTunable) != std::string::npos)
    return std::string("malloc takes transparent huge pages (GLIBC_TUNABLES=") + *env.glibc_tunables + ")";
  if (const auto reason = reason_not_to_restart(env)) return "malloc as the C library starts it: " + *reason;
  return "malloc as the C library starts it (umbra restarts itself with GLIBC_TUNABLES=" + std::string(kTunable) + ")";
}

void restart_with_huge_page_malloc(char** argv) {
  if (reason_not_to_restart(current_malloc_environment())) return;
  if (setenv("GLIBC_TUNABLES", kTunable, 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("GLIBC_TUNABLES");  // exec failed (no /proc): go on as started
}

}  // namespace umbra
