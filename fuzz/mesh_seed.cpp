// Writes the mesh fuzzers' seed corpus: each FILE into OUTDIR under its own
// name (numbered), behind the byte that names its format (format_byte.hpp), so that
// build.sh need not know how formats are numbered. Files of no mesh format
// are left out. --every-reader numbers them for library_fuzzer.
//   mesh_seed [--every-reader] OUTDIR FILE...
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "fuzz/format_byte.hpp"

int main(int argc, char** argv) {
  const bool every = argc > 1 && std::string(argv[1]) == "--every-reader";
  const int first = every ? 2 : 1;
  if (argc <= first) {
    std::cerr << "usage: mesh_seed [--every-reader] OUTDIR FILE...\n";
    return 2;
  }
  const std::filesystem::path folder = argv[first];
  const auto readers = every ? umbra::fuzz::Readers::kEvery : umbra::fuzz::Readers::kUmbras;
  for (int i = first + 1; i < argc; ++i) {
    const std::optional<uint8_t> byte = umbra::fuzz::mesh_format_byte_of(argv[i], readers);
    if (!byte) continue;
    std::ifstream in(argv[i], std::ios::binary);
    // Numbered: folders of test models hold files of one name.
    std::ofstream out(folder / (std::to_string(i) + "-" + std::filesystem::path(argv[i]).filename().string()), std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    out.put(char(*byte));
    out << bytes;
    if (!in.is_open() || !out) {
      std::cerr << "mesh_seed: cannot copy " << argv[i] << " into " << folder << "\n";
      return 1;
    }
  }
  return 0;
}
