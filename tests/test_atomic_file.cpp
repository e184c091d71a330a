// Tests for io/atomic_file.hpp beyond all-or-nothing commits (test_config.cpp): inputs are never
// replaced, a failed commit removes what it created, and a signal removes every temporary
// (issue 9, D04, D05, D19).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "temp_dir.hpp"

using namespace selfalign;
using namespace selfalign::testing;
namespace fs = std::filesystem;

namespace {
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}
}  // namespace

TEST(AtomicFileSet, NeverReplacesARegisteredInput) {
  forget_run_files();
  TempDir dir;
  write_text(dir.file("in.toml"), "periods = 2\n");
  register_input_file(dir.file("in.toml"), "--config");
  EXPECT_EQ(input_file_flag(dir.file("in.toml")), "--config");
  // Also under another spelling of the same file, and through a link to it.
  fs::create_symlink(dir.file("in.toml"), dir.file("link.toml"));
  EXPECT_EQ(input_file_flag(dir.path().string() + "/./in.toml"), "--config");
  EXPECT_EQ(input_file_flag(dir.file("link.toml")), "--config");
  EXPECT_FALSE(input_file_flag(dir.file("other.toml")).has_value());
  AtomicFileSet files;
  try {
    files.add(dir.file("link.toml"), "overwritten", "out");
    FAIL() << "an input was accepted as an output";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), "out");
    EXPECT_NE(e.allowed().find("--config"), std::string::npos);
  }
  EXPECT_EQ(read_text(dir.file("in.toml")), "periods = 2\n");
  SimulateConfig config;  // an input named in a config but not read yet
  config.samples = dir.file("s.csv");
  config.out = dir.file("./s.csv");
  EXPECT_THROW(resolve_output_paths(config), InvalidParameter);
}

TEST(AtomicFileSet, FailedCommitRemovesTheFilesItCreated) {
  forget_run_files();
  TempDir dir;
  AtomicFileSet files;
  files.add(dir.file("a.csv"), "alpha", "out");
  files.add(dir.file("b.json"), "beta", "summary");
  // Between add and commit the second target becomes a folder: its rename fails.
  fs::create_directory(dir.file("b.json"));
  fs::create_directory(dir.file("b.json/x"));  // not empty: rename(2) cannot replace it
  EXPECT_THROW(files.commit(), InvalidParameter);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"b.json"});  // a.csv undone, no temps
}

// D19: SIGINT while a set holds temporaries removes them, and the process still dies of the
// signal (its exit status says so).
TEST(AtomicFileSet, SignalRemovesTemporariesAndKeepsItsMeaning) {
  TempDir dir;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    remove_temporaries_on_signals();
    AtomicFileSet files;
    files.add(dir.file("big.csv"), std::string(1 << 20, 'x'), "out");  // a temporary now exists
    ::raise(SIGINT);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_TRUE(entries(dir.path()).empty()) << entries(dir.path()).front();
}
