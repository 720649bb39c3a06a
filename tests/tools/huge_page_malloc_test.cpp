// When umbra restarts itself with glibc's huge-page malloc, and what it says
// about it: the decision for each environment, and the restart itself.
#include <gtest/gtest.h>

#include "tests/tools/command_fixture.hpp"
#include "tools/huge_page_malloc.hpp"

namespace umbra {
namespace {

#if defined(__GLIBC__)
#if __GLIBC_PREREQ(2, 35)

MallocEnvironment plain_environment(const std::string& modes = "always [madvise] never\n") {
  MallocEnvironment env;
  env.transparent_huge_pages = modes;
  return env;
}

TEST(HugePageMalloc, RestartsWhereTheKernelGivesHugePagesOnRequestAndNobodyElseHasASay) {
  EXPECT_EQ(reason_not_to_restart(plain_environment()), std::nullopt);
  EXPECT_EQ(malloc_pages_description(plain_environment()),
            "malloc as the C library starts it (umbra restarts itself with GLIBC_TUNABLES=glibc.malloc.hugetlb=1)");
}

TEST(HugePageMalloc, LeavesTheKernelsOtherModesAlone) {
  EXPECT_EQ(reason_not_to_restart(plain_environment("[always] madvise never\n")),
            "the kernel gives large blocks transparent huge pages unasked");
  EXPECT_EQ(reason_not_to_restart(plain_environment("always madvise [never]\n")),
            "the kernel's transparent huge pages are off (never)");
  EXPECT_EQ(reason_not_to_restart(plain_environment("")), "this kernel offers no transparent huge pages");
}

TEST(HugePageMalloc, LeavesTheUsersTunablesPreloadsAndSanitizersAlone) {
  MallocEnvironment tuned = plain_environment();
  tuned.glibc_tunables = "";  // set, even empty: the user's choice
  EXPECT_EQ(reason_not_to_restart(tuned), "GLIBC_TUNABLES is set, and umbra leaves it as it is");
  EXPECT_EQ(malloc_pages_description(tuned),
            "malloc as the C library starts it: GLIBC_TUNABLES is set, and umbra leaves it as it is");

  MallocEnvironment preloaded = plain_environment();
  preloaded.ld_preload = "/usr/lib/x86_64-linux-gnu/libjemalloc.so.2";
  EXPECT_EQ(reason_not_to_restart(preloaded), "LD_PRELOAD is set (a profiler or another malloc may be in charge)");

  MallocEnvironment sanitized = plain_environment();
  sanitized.sanitizer_allocator = true;
  EXPECT_EQ(reason_not_to_restart(sanitized), "AddressSanitizer's allocator is in charge of memory");

  MallocEnvironment loaded = plain_environment();
  loaded.started_by_loader = true;
  EXPECT_EQ(reason_not_to_restart(loaded), "umbra was started through the dynamic loader, which a restart would run instead");
}

TEST(HugePageMalloc, SaysSoWhenTheTunableIsInTheEnvironment) {
  MallocEnvironment restarted = plain_environment();
  restarted.glibc_tunables = "glibc.malloc.hugetlb=1";
  EXPECT_EQ(malloc_pages_description(restarted), "malloc takes transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1)");
  restarted.glibc_tunables = "glibc.malloc.check=0:glibc.malloc.hugetlb=1";
  EXPECT_EQ(malloc_pages_description(restarted),
            "malloc takes transparent huge pages (GLIBC_TUNABLES=glibc.malloc.check=0:glibc.malloc.hugetlb=1)");
}

#endif
#endif

class HugePageRestart : public test::CommandTest {};

// The restart as it happens: umbra started without GLIBC_TUNABLES reports
// the tunable in its own environment where this kernel takes requests for
// huge pages, and the reason it went without elsewhere.
TEST_F(HugePageRestart, TheRestartedProcessHasTheTunable) {
  const MallocEnvironment here = current_malloc_environment();
  if (here.sanitizer_allocator) GTEST_SKIP() << "AddressSanitizer's allocator: no restart";
  const test::CommandResult version = run("--version", "env -u GLIBC_TUNABLES -u LD_PRELOAD ");
  ASSERT_EQ(version.status, 0) << version.err;
  MallocEnvironment unset = here;
  unset.glibc_tunables.reset();
  unset.ld_preload.reset();
  const std::string expected = reason_not_to_restart(unset)
                                   ? malloc_pages_description(unset)
                                   : "malloc takes transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1)";
  EXPECT_NE(version.out.find("\nmemory: " + expected + "\n"), std::string::npos) << version.out;
}

TEST_F(HugePageRestart, AnEmptyTunablesVariableKeepsTheDefault) {
  if (current_malloc_environment().sanitizer_allocator) GTEST_SKIP() << "AddressSanitizer's allocator: no restart";
  const test::CommandResult version = run("--version", "env GLIBC_TUNABLES= ");
  ASSERT_EQ(version.status, 0) << version.err;
  EXPECT_NE(version.out.find("\nmemory: malloc as the C library starts it: GLIBC_TUNABLES is set, and umbra leaves it as it is\n"),
            std::string::npos)
      << version.out;
}

// Started as "ld.so umbra ...", umbra is umbra: a restart of /proc/self/exe
// would run the loader with umbra's arguments (its --version, or exit 127).
TEST_F(HugePageRestart, StartedThroughTheDynamicLoaderUmbraStaysUmbra) {
  const std::string loader = "/lib64/ld-linux-x86-64.so.2";
  if (!std::filesystem::exists(loader)) GTEST_SKIP() << "no " << loader << " on this machine";
  const test::CommandResult version = run("--version", "env -u GLIBC_TUNABLES -u LD_PRELOAD " + loader + " ");
  ASSERT_EQ(version.status, 0) << version.err;
  EXPECT_EQ(version.out.rfind("umbra ", 0), 0u) << version.out;
  if (!current_malloc_environment().sanitizer_allocator) {
    EXPECT_NE(version.out.find("\nmemory: malloc as the C library starts it: umbra was started through the dynamic loader, which a "
                               "restart would run instead\n"),
              std::string::npos)
        << version.out;
  }
  const test::CommandResult check = run("check " + write("t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), loader + " ");
  EXPECT_NE(check.status, 127) << check.err;
  EXPECT_NE(check.out.find("t.off"), std::string::npos) << check.out << check.err;
}

}  // namespace
}  // namespace umbra
