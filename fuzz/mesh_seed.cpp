// Writes the mesh fuzzer's seed corpus: each FILE into OUTDIR under its own
// name, behind the byte that names its format (format_byte.hpp), so that
// build.sh need not know how formats are numbered. Files of no mesh format
// are left out.
//   mesh_seed OUTDIR FILE...
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>

#include "fuzz/format_byte.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: mesh_seed OUTDIR FILE...\n";
    return 2;
  }
  const std::filesystem::path folder = argv[1];
  for (int i = 2; i < argc; ++i) {
    const std::optional<uint8_t> byte = umbra::fuzz::mesh_format_byte_of(argv[i]);
    if (!byte) continue;
    std::ifstream in(argv[i], std::ios::binary);
    std::ofstream out(folder / std::filesystem::path(argv[i]).filename(), std::ios::binary);
    out.put(char(*byte));
    out << in.rdbuf();
    if (!in || !out) {
      std::cerr << "mesh_seed: cannot copy " << argv[i] << " into " << folder << "\n";
      return 1;
    }
  }
  return 0;
}
