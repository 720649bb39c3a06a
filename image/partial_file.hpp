#pragma once
// An output file written under a temporary name beside its final one and
// renamed into place once whole, so that nobody ever sees part of it. Each
// writer's temporary name is its own (the final name, cut short where it
// must be to stay a legal name, a random part and ".partial"), so that two
// writers of one name never meet, and a process stopped by SIGINT or
// SIGTERM removes every temporary file it had open
// (remove_partial_files_on_signals).

#include <optional>
#include <string>

namespace umbra {

// A path removed if SIGINT, SIGTERM or SIGHUP ends the process while this
// lives (remove_partial_files_on_signals): a file, or a folder, removed
// once the files are.
class RemovedOnSignals {
 public:
  enum class Kind { kFile, kFolder };
  explicit RemovedOnSignals(const std::string& path, Kind kind = Kind::kFile);
  ~RemovedOnSignals() { release(); }
  RemovedOnSignals(const RemovedOnSignals&) = delete;
  RemovedOnSignals& operator=(const RemovedOnSignals&) = delete;
  void release();  // no longer removed

 private:
  int slot_ = -1;  // in the list the signal handler removes; -1 when the list was full
};

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
  std::optional<RemovedOnSignals> listed_;
  bool committed_ = false;
  bool in_place_ = false;  // a FIFO or device, written as it is
};

// Removes the temporary files of `path` that writers left behind when they
// were killed (SIGKILL, a crash: no handler ran), as a parent whose worker
// died while it wrote `path` does. Another writer of the same name at the
// same moment would lose its temporary file too: callers own the name.
void remove_abandoned_temporaries(const std::string& path, PartialFile::Ending ending = PartialFile::Ending::kPartial);
// The same for every file a killed writer was writing in `folder`, which
// the caller owns outright (one model's views): any temporary file there.
void remove_abandoned_temporaries_in(const std::string& folder);

// Makes SIGINT and SIGTERM remove every PartialFile's temporary file before
// the process ends as the signal would end it. Called once, by main.
void remove_partial_files_on_signals();

}  // namespace umbra
