#pragma once
// Faults that a test build (umbra_fault_injected, built with
// UMBRA_FAULT_INJECTION) meets on purpose, by a file's name, as a render or
// a check of a corpus could meet them: a crash ("crash"), an allocation that
// fails ("out-of-memory"), the kernel's OOM killer ("oom-killed") and a
// hang ("hang"). umbra itself has none of them.

#include <string>

#ifdef UMBRA_FAULT_INJECTION
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <new>

namespace umbra {

inline void inject_fault(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (name.find("crash") != std::string::npos) std::abort();
  if (name.find("out-of-memory") != std::string::npos) throw std::bad_alloc();
  if (name.find("oom-killed") != std::string::npos) ::raise(SIGKILL);
  if (name.find("hang") != std::string::npos)
    for (;;) ::pause();
}

}  // namespace umbra
#else
namespace umbra {
inline void inject_fault(const std::string&) {}
}  // namespace umbra
#endif
