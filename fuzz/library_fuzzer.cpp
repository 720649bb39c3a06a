// libFuzzer target: mesh files through every reader, libraries' included
// (see fuzz_entries.hpp).
#include "fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  umbra::fuzz::library_input(data, size);
  return 0;
}
