#pragma once
// A file's bytes, memory-mapped read-only: no copy and no buffer to fill, so
// a mesh file of hundreds of megabytes costs only the pages a reader touches.

#include <string>
#include <string_view>

namespace umbra {

class MappedFile {
 public:
  // Throws InputError naming `path` when it cannot be opened or mapped.
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace umbra
