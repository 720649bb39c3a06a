#pragma once
// An output file written under a temporary name beside its final one and
// renamed into place once whole, so that nobody ever sees part of it. Each
// writer's temporary name is its own (the final name, cut short where it
// must be to stay a legal name, a random part and ".partial"), so that two writers of one name never meet, and a process
// stopped by SIGINT or SIGTERM removes every temporary file it had open
// (remove_partial_files_on_signals).

#include <string>

namespace umbra {

class PartialFile {
 public:
  // Creates the temporary file for `path`; throws std::runtime_error, "PATH:
  // cannot write WHAT: why", when it cannot, or when `path` is a folder or a
  // block device. Where `path` is a FIFO or a character device (/dev/null,
  // /dev/stdout), it is written in place: the temporary path is `path`. The temporary name ends as
  // `path` does (PATH.XXXXXX.partial.EXT) where a writer tells the format by
  // the extension.
  enum class Ending { kPartial, kKeepExtension };
  PartialFile(const std::string& path, const std::string& what, Ending ending = Ending::kPartial);
  ~PartialFile();  // removes the temporary file, unless committed
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  // Where to write: an empty file, created for this writer alone.
  const std::string& temporary_path() const { return temporary_; }
  // The final path, as given.
  const std::string& path() const { return path_; }
  // Renames the temporary file to the final path; throws std::runtime_error.
  void commit();

 private:
  std::string path_, what_, temporary_;
  int slot_ = -1;  // in the list the signal handler removes; -1 when the list was full
  bool committed_ = false;
  bool in_place_ = false;  // a FIFO or device, written as it is
};

// Makes SIGINT and SIGTERM remove every PartialFile's temporary file before
// the process ends as the signal would end it. Called once, by main.
void remove_partial_files_on_signals();

}  // namespace umbra
