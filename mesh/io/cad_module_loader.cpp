// Opens the CAD reader's module (umbra-cad.so) on first use: beside an
// installed umbra (its lib/umbra), beside an installed Python module, or
// in the build tree it was built in; whichever loads first.

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <vector>

#include "mesh/input_error.hpp"
#include "mesh/io/mesh_readers.hpp"

namespace umbra {
namespace {

ReadCadEntry cad_entry(std::string& why) {
  static std::once_flag once;
  static ReadCadEntry entry = nullptr;
  static std::string failure;
  std::call_once(once, [] {
    // The executable or the Python module this code is part of.
    Dl_info self{};
    std::filesystem::path here;
    if (dladdr(reinterpret_cast<void*>(&cad_entry), &self) && self.dli_fname)
      here = std::filesystem::path(self.dli_fname).parent_path();
    std::vector<std::filesystem::path> candidates;
    if (!here.empty())
      for (const char* relative : {UMBRA_CAD_MODULE_FROM_BINDIR, UMBRA_CAD_MODULE_FROM_PYTHONDIR})
        candidates.push_back(here / relative / kCadModule);
    candidates.push_back(std::filesystem::path(UMBRA_CAD_MODULE_BUILT) / kCadModule);
    for (const std::filesystem::path& candidate : candidates) {
      std::error_code ec;
      if (!std::filesystem::exists(candidate, ec)) continue;
      if (void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL)) {
        entry = reinterpret_cast<ReadCadEntry>(dlsym(module, kReadCadEntry));
        if (entry) return;
        failure = candidate.string() + " has no " + kReadCadEntry;
      } else {
        failure = dlerror();
      }
    }
    if (failure.empty()) failure = std::string("umbra's CAD reader, ") + kCadModule + ", is missing: reinstall umbra";
  });
  why = failure;
  return entry;
}

}  // namespace

PolygonSoup read_cad(std::string_view bytes, const std::string& path, CadFormat format, const CadTessellation& tessellation) {
  std::string why;
  const ReadCadEntry entry = cad_entry(why);
  if (!entry) throw InputError({path, 0, 0}, std::string(cad_format_name(format)) + " files need Open CASCADE: " + why);
  PolygonSoup soup;
  std::string error;
  if (!entry(bytes.data(), bytes.size(), path.c_str(), int(format), &tessellation, &soup, &error)) throw InputError({path, 0, 0}, error);
  return soup;
}

}  // namespace umbra
