// Outputs published as a unit (src/core/output_stage.hpp): nothing appears before publish(), the
// index files move last, an abandoned stage leaves nothing, and what dead processes left is removed.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

#include "core/atomic_file.hpp"
#include "core/output_stage.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;
namespace fs = std::filesystem;

namespace {

/// A pid no process has now (kill(pid, 0) reports ESRCH).
long dead_pid() {
  for (long pid = 4000000; pid > 1000; pid -= 7919)
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) return pid;
  return 0;
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST(OutputStage, FilesAppearOnlyWhenPublishedAndReplaceOlderOnes) {
  const test::ScratchDirectory scratch;
  const fs::path out = scratch / "out";
  fs::create_directories(out);
  write_text_file(out / "a.txt", "old");
  {
    OutputStage stage(out);
    write_text_file(stage.path() / "a.txt", "new");
    write_text_file(stage.path() / "metrics.json", "{}");
    EXPECT_EQ(names_in(out), (std::vector<std::string>{".staging-" + std::to_string(::getpid()), "a.txt"}));
    std::ifstream old(out / "a.txt");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(old), {}), "old") << "not replaced before publish()";
    stage.publish({"metrics.json"});
  }
  EXPECT_EQ(names_in(out), (std::vector<std::string>{"a.txt", "metrics.json"})) << "staging folder removed";
  std::ifstream now(out / "a.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(now), {}), "new");
}

TEST(OutputStage, AnAbandonedStageLeavesNothing) {
  const test::ScratchDirectory scratch;
  {
    OutputStage stage(scratch.path());
    write_text_file(stage.path() / "half.exr", "x");
  }  // e.g. an exception before publish()
  EXPECT_TRUE(names_in(scratch.path()).empty());
}

TEST(OutputStage, TemporariesOfDeadProcessesAreRemovedAndLiveOnesKept) {
  const test::ScratchDirectory scratch;
  const long dead = dead_pid();
  ASSERT_GT(dead, 0);
  const std::string mine = std::to_string(::getpid()), gone = std::to_string(dead);
  write_text_file(scratch / (".tmp-" + gone + "-reference.exr"), "x");  // what SIGKILL left
  fs::create_directories(scratch / (".staging-" + gone));
  write_text_file(scratch / (".staging-" + gone) / "conventional.exr", "x");
  write_text_file(scratch / (".tmp-" + mine + "-busy.exr"), "x");  // a live writer's
  write_text_file(scratch / ".tmp-notapid-keep.txt", "x");           // not ours to judge
  remove_stale_temporaries(scratch.path());
  EXPECT_EQ(names_in(scratch.path()), (std::vector<std::string>{".tmp-" + mine + "-busy.exr", ".tmp-notapid-keep.txt"}));
}
