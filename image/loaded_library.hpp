#pragma once
// A shared library opened at run time (dlopen), for what umbra loads only
// when it uses it: the GL platforms when it draws (libEGL, libOSMesa), and
// libavcodec's hundred-odd libraries when it writes a video, which every
// other run would otherwise load and map at its start.

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace umbra {

class LoadedLibrary {
 public:
  // Opens the first of `files` that loads; throws std::runtime_error
  // "PLATFORM: cannot load WHAT: <dlerror>" when none does. It stays loaded
  // for the life of the process.
  LoadedLibrary(const std::string& platform, const std::vector<const char*>& files, const std::string& what)
      : platform_(platform) {
    for (const char* file : files)
      if ((handle_ = dlopen(file, RTLD_NOW | RTLD_LOCAL))) return;
    throw std::runtime_error(platform + ": cannot load " + what + ": " + dlerror());
  }

  // Sets `out` to the library's function `name`, or throws naming it.
  template <typename Function>
  void resolve(const char* name, Function& out) const {
    out = reinterpret_cast<Function>(dlsym(handle_, name));
    if (!out) throw std::runtime_error(platform_ + ": the library has no " + name);
  }

 private:
  std::string platform_;
  void* handle_ = nullptr;
};

}  // namespace umbra
