// libFuzzer target: transforms.json files for umbra render --cameras (see fuzz_entries.hpp).
#include "fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  umbra::fuzz::cameras_input(data, size);
  return 0;
}
