// libFuzzer target: mesh files of every format (see fuzz_entries.hpp).
#include "fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  umbra::fuzz::mesh_input(data, size);
  return 0;
}
