#pragma once
// A file's bytes, memory-mapped read-only: no copy and no buffer to fill, so
// a mesh file of hundreds of megabytes costs only the pages a reader touches.
//
// A file cut short while it is mapped would end the process with SIGBUS
// (the pages past its new end no longer exist). A handler, installed with
// the first mapping, maps a page of zeros over any such page of a live
// MappedFile and marks it cut short; readers then read zeros there, and
// whoever reads it asks cut_short() and says the file changed.

#include <string>
#include <string_view>

namespace umbra {

// What a file that is not a regular file is, as `st_mode` says: "a folder",
// "a FIFO", "a character device", ... Only regular files are read: a FIFO or
// a device could be endless, or never answer.
std::string non_regular_kind(unsigned mode);

class MappedFile {
 public:
  // Throws InputError naming `path` when it cannot be opened or mapped, or
  // is not a regular file (opened without waiting: a FIFO never blocks it).
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return {data_, size_}; }
  // Some page was read after the file shrank under it: what was read there is zeros.
  bool cut_short() const;

 private:
  const char* data_ = nullptr;
  size_t size_ = 0;
  int slot_ = -1;  // in the handler's table of live mappings; -1 when none was free
};

}  // namespace umbra
