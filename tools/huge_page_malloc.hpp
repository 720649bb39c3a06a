#pragma once
// glibc's malloc takes memory from the kernel 4 KiB at a time, and the first
// touch of each page is a fault: on a virtual machine, several microseconds
// apiece, a fifth to a third of a large render or check (Mesa's software
// rasteriser allocates as freely as umbra does). With the tunable
// glibc.malloc.hugetlb=1 (glibc 2.35 and later) malloc asks the kernel for
// transparent huge pages of 2 MiB instead, and a large render's faults drop
// several times over (docs/performance.md, "Huge pages for malloc, and one
// heap"). glibc reads tunables only from the environment when a process
// starts, so umbra sets GLIBC_TUNABLES and starts itself again, once, before
// it does any work.
#include <optional>
#include <string>

namespace umbra {

// What the restart depends on: the environment and the kernel's setting.
struct MallocEnvironment {
  std::optional<std::string> glibc_tunables;  // GLIBC_TUNABLES, if set (even empty)
  std::optional<std::string> ld_preload;      // LD_PRELOAD, if set
  std::string transparent_huge_pages;         // /sys/kernel/mm/transparent_hugepage/enabled, "" if absent
  bool sanitizer_allocator = false;           // built with AddressSanitizer, whose malloc is its own
  // Started through the dynamic loader ("ld.so umbra ..."): /proc/self/exe
  // is then the loader, and restarting it would run the loader with umbra's
  // arguments.
  bool started_by_loader = false;
};

// This process's environment and kernel.
MallocEnvironment current_malloc_environment();

// Why umbra does not restart itself with huge pages, or nothing when it
// should: only where the kernel gives huge pages on request ("madvise") and
// nobody else has a say in malloc (GLIBC_TUNABLES, set even empty, is the
// user's choice, and LD_PRELOAD means a profiler or another malloc).
std::optional<std::string> reason_not_to_restart(const MallocEnvironment& env);

// One line for --version and --explain: which pages malloc takes, and why.
std::string malloc_pages_description(const MallocEnvironment& env);

// Runs this executable again (/proc/self/exe, the same arguments) with
// GLIBC_TUNABLES=glibc.malloc.hugetlb=1 where reason_not_to_restart finds
// none. Returns only where it does not restart, or where exec fails.
void restart_with_huge_page_malloc(char** argv);

}  // namespace umbra
