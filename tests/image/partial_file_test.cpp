// Output files are written under a temporary name of their writer's own and
// renamed into place; SIGINT or SIGTERM while one is written leaves nothing.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "image/partial_file.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

class PartialFiles : public test::ScratchFolder {
 protected:
  size_t files_in_folder() const {
    size_t n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder_)) ++n;
    return n;
  }
};

TEST_F(PartialFiles, TwoWritersOfOneNameNeverShareATemporaryFile) {
  const std::string out = (folder_ / "x.png").string();
  PartialFile a(out, "the image"), b(out, "the image");
  EXPECT_NE(a.temporary_path(), b.temporary_path());
  EXPECT_EQ(a.temporary_path().rfind(out + ".", 0), 0u);
  std::ofstream(a.temporary_path()) << "a";
  std::ofstream(b.temporary_path()) << "b";
  a.commit();
  EXPECT_EQ(files_in_folder(), 2u);  // x.png and b's
  b.commit();
  EXPECT_EQ(files_in_folder(), 1u);
  std::ifstream in(out);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "b");
}

// A writer that tells the format by the extension (CGAL's) gets one.
// A FIFO or a character device named as the output (-o /dev/null, to time a
// render) is written in place: renaming a temporary file over it would
// replace the device itself, which root may do (and /dev/null is then a
// file). The FIFO is still one afterwards, and its reader got the bytes.
TEST_F(PartialFiles, AFifoOrDeviceIsWrittenInPlaceNeverReplaced) {
  const std::string fifo = (folder_ / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string read;
  {
    PartialFile out(fifo, "the image");
    ASSERT_EQ(out.temporary_path(), fifo);
    std::thread reader([&] {
      std::ifstream in(fifo);
      read.assign(std::istreambuf_iterator<char>(in), {});
    });
    std::ofstream(out.temporary_path()) << "bytes";
    out.commit();
    reader.join();
  }
  EXPECT_EQ(read, "bytes");
  ASSERT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_EQ(files_in_folder(), 1u);
  PartialFile null("/dev/null", "the image");
  EXPECT_EQ(null.temporary_path(), "/dev/null");
  null.commit();
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

// A name of the longest length a folder allows (255 bytes) is legal, and so
// is writing it: the temporary name, 15 bytes longer, once failed with "File
// name too long".
TEST_F(PartialFiles, TheLongestLegalNameIsWritten) {
  for (const size_t length : {240u, 241u, 250u, 255u}) {
    const std::string name = std::string(length - 4, 'n') + ".png";
    const std::string path = (folder_ / name).string();
    {
      PartialFile out(path, "the image", PartialFile::Ending::kKeepExtension);
      EXPECT_EQ(std::filesystem::path(out.temporary_path()).extension(), ".png");
      std::ofstream(out.temporary_path()) << "bytes";
      out.commit();
    }
    EXPECT_TRUE(std::filesystem::is_regular_file(path)) << length;
    EXPECT_EQ(files_in_folder(), 1u) << length;
    std::filesystem::remove(path);
  }
}

TEST_F(PartialFiles, AFolderOrABlockDeviceIsNoPlaceForAFile) {
  try {
    PartialFile out(folder_.string(), "the image");
    FAIL() << "a folder was taken for a file";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), folder_.string() + ": cannot write the image: it is a folder");
  }
}

// A file written whole gets the mode any new file gets (0666 less the
// umask), not the 0600 of its private temporary file.
TEST_F(PartialFiles, AWrittenFileIsReadableAsAnyNewFileIs) {
  const std::string out = (folder_ / "x.png").string();
  const mode_t before = ::umask(022);
  {
    PartialFile file(out, "the image");
    file.commit();
  }
  ::umask(before);
  struct stat info {};
  ASSERT_EQ(::stat(out.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);
}

TEST_F(PartialFiles, TheExtensionStaysLastWhereAsked) {
  const std::string out = (folder_ / "repaired.off").string();
  const PartialFile a(out, "the mesh", PartialFile::Ending::kKeepExtension), b(out, "the mesh");
  EXPECT_EQ(a.temporary_path().substr(out.size() + 7), ".partial.off");
  EXPECT_EQ(b.temporary_path().substr(out.size() + 7), ".partial");
}

TEST_F(PartialFiles, AWriterGivenUpLeavesNothing) {
  { PartialFile a((folder_ / "x.png").string(), "the image"); }
  EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(PartialFiles, SigtermOrSigintWhileWritingLeavesNothing) {
  for (const int signal_number : {SIGTERM, SIGINT}) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      remove_partial_files_on_signals();
      PartialFile a((folder_ / "x.png").string(), "the image"), b((folder_ / "y.png").string(), "the image");
      std::ofstream(a.temporary_path()) << "half a picture";
      ::raise(signal_number);
      ::_exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << status;  // ended as the signal ends it
    EXPECT_EQ(files_in_folder(), 0u);
  }
}

TEST_F(PartialFiles, AFolderThatCannotBeWrittenSaysWhy) {
  try {
    PartialFile((folder_ / "missing" / "x.png").string(), "the image");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (folder_ / "missing" / "x.png").string() + ": cannot write the image: No such file or directory");
  }
}

}  // namespace
}  // namespace umbra
