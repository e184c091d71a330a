// Tests for the CLI's handling of files (issue 9, D04-D06, D18, D21, P01): an output never
// replaces an input, a FIFO, a device or a symbolic link; a failed run leaves nothing behind; a
// replaced file keeps its mode; "-" is standard output; a summary-only run samples nothing.
#include <gtest/gtest.h>

#include "cli_sandbox.hpp"

#ifdef SELFALIGN_CLI_PATH

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

using namespace selfalign::testing;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char kSamples[] = "t,ydd\n0,1\n0.5,-1\n1,0\n";  // y'' = +1 then -1: velocity returns

}  // namespace

// D05: --out, or the default summary beside it, naming an input file is refused before the run;
// the input is unchanged.
TEST(CliFiles, OutputNamingAnInputIsRefusedAndTheInputKept) {
  CliSandbox box;
  write_text(box.work_file("cfg.toml"), "periods = 2.0\n");
  CliResult r = box.run({"simulate", "--config", "cfg.toml", "--out", "cfg.toml"});
  expect_one_line_error(r, {"out = cfg.toml", "--config"});
  EXPECT_EQ(read_text(box.work_file("cfg.toml")), "periods = 2.0\n");

  write_text(box.work_file("run.summary.json"), R"({"periods": 2.0})");
  r = box.run({"simulate", "--config", "run.summary.json", "--out", "run.csv"});
  expect_one_line_error(r, {"summary = run.summary.json", "--config"});
  EXPECT_EQ(read_text(box.work_file("run.summary.json")), R"({"periods": 2.0})");

  write_text(box.work_file("s.csv"), kSamples);
  r = box.run({"simulate", "--profile", "samples", "--samples", "s.csv", "--periods", "1",
               "--out", "s.csv"});
  expect_one_line_error(r, {"out = s.csv", "--samples"});
  EXPECT_EQ(read_text(box.work_file("s.csv")), kSamples);

  // Through a symbolic link to the config, and from a key inside the config itself.
  fs::create_symlink("cfg.toml", box.work_file("link.toml"));
  r = box.run({"steady", "--config", "cfg.toml", "--out", "link.toml"});
  expect_one_line_error(r, {"link.toml", "--config"});
  write_text(box.work_file("self.json"), R"({"out": "self.json"})");
  r = box.run({"simulate", "--config", "self.json"});
  expect_one_line_error(r, {"self.json", "--config"});
  EXPECT_EQ(read_text(box.work_file("self.json")), R"({"out": "self.json"})");
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"cfg.toml", "link.toml",
                                                         "run.summary.json", "s.csv", "self.json"}));
}

// D04: a summary path taken by a folder is refused before the run: no CSV is left behind.
TEST(CliFiles, SummaryPathThatIsAFolderLeavesNoCsv) {
  CliSandbox box;
  fs::create_directory(box.work_file("run.summary.json"));
  const CliResult r = box.run({"simulate", "--periods", "2", "--out", "run.csv"});
  expect_one_line_error(r, {"summary = run.summary.json", "directory"});
  EXPECT_EQ(box.work_entries(), std::vector<std::string>{"run.summary.json"});
}

// D06: a folder or an empty name as --config, an empty value for a number option.
TEST(CliFiles, FolderOrEmptyConfigAndEmptyNumbersAreRefused) {
  CliSandbox box;
  fs::create_directory(box.work_file("run.toml"));
  expect_one_line_error(box.run({"steady", "--config", "run.toml"}), {"config file", "directory"});
  // A FIFO nobody writes would block the read for ever (fuzz seed 13): not a regular file.
  ASSERT_EQ(::mkfifo(box.work_file("pipe.json").c_str(), 0644), 0);
  expect_one_line_error(box.run({"steady", "--config", "pipe.json"}), {"config file", "regular"});
  expect_one_line_error(box.run({"steady", "--config", ""}), {"--config", "empty"});
  expect_one_line_error(box.run({"optimize", "--seed", "", "--quiet"}), {"--seed", "empty"});
  expect_one_line_error(box.run({"steady", "--a2", "1e-999"}), {"a2"});
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"pipe.json", "run.toml"}));
}

// D18: `--out=` followed by a flag would have taken the flag as the file name.
TEST(CliFiles, FileOptionRefusesAFlagAsItsValue) {
  CliSandbox box;
  expect_one_line_error(box.run({"steady", "--out=", "--json"}), {"--out", "--json"});
  expect_one_line_error(box.run({"simulate", "--summary=", "--quiet"}), {"--summary"});
  EXPECT_TRUE(box.work_entries().empty());
}

// D21: a replaced file keeps its mode; a symbolic link keeps pointing at its (updated) target.
TEST(CliFiles, ReplacedFileKeepsItsModeAndALinkItsTarget) {
  CliSandbox box;
  write_text(box.work_file("mode600.csv"), "old\n");
  ASSERT_EQ(::chmod(box.work_file("mode600.csv").c_str(), 0600), 0);
  CliResult r = box.run({"simulate", "--periods", "1", "--out", "mode600.csv"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  struct stat st {};
  ASSERT_EQ(::stat(box.work_file("mode600.csv").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
  EXPECT_EQ(read_text(box.work_file("mode600.csv")).rfind("t,x,x_dot", 0), 0u);

  fs::create_directory(box.work_file("target"));
  write_text(box.work_file("target/t.csv"), "old\n");
  fs::create_symlink("target/t.csv", box.work_file("link.csv"));
  r = box.run({"simulate", "--periods", "1", "--out", "link.csv", "--summary", "s.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(box.work_file("link.csv")));
  EXPECT_EQ(read_text(box.work_file("target/t.csv")).rfind("t,x,x_dot", 0), 0u);
  EXPECT_EQ(box.work_entries(), (std::vector<std::string>{"link.csv", "mode600.csv",
                                                         "mode600.summary.json", "s.json",
                                                         "target"}));
}

// D21: a FIFO is written into, never replaced; one nobody reads is an error, not a hang, and
// then no other output lands either.
TEST(CliFiles, FifoIsWrittenIntoAndNeverReplaced) {
  CliSandbox box;
  const std::string fifo = box.work_file("pipe.csv");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  CliResult r = box.run({"simulate", "--periods", "1", "--out", "pipe.csv"});
  expect_one_line_error(r, {"out = ", "pipe.csv", "no reader"});
  EXPECT_EQ(box.work_entries(), std::vector<std::string>{"pipe.csv"});  // no summary landed

  // With a reader (this test, holding the read end open): the CSV arrives through the pipe.
  // One period is ~16 KB, less than a pipe's buffer, so the CLI never waits on the reader.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  r = box.run({"simulate", "--periods", "1", "--out", "pipe.csv", "--summary", "s.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string piped;
  char buffer[4096];
  for (ssize_t n; (n = ::read(reader, buffer, sizeof buffer)) > 0;) piped.append(buffer, n);
  ::close(reader);
  EXPECT_EQ(piped.rfind("t,x,x_dot", 0), 0u) << piped.substr(0, 80);
  EXPECT_EQ(piped.back(), '\n');
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

// "-" is standard output: the CSV goes there and no file named "-" appears; the summary then
// needs a file of its own.
TEST(CliFiles, DashIsStandardOutput) {
  CliSandbox box;
  CliResult r = box.run({"simulate", "--periods", "1", "--out", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("t,x,x_dot", 0), 0u);
  EXPECT_TRUE(box.work_entries().empty());
  r = box.run({"simulate", "--periods", "1", "--out", "-", "--summary", "-"});
  expect_one_line_error(r, {"summary", "standard output"});
  r = box.run({"simulate", "--periods", "1", "--out", "-", "--summary", "s.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(box.work_entries(), std::vector<std::string>{"s.json"});
}

// P01: without --out nothing is sampled: the summary says so (stick_fraction null), and a long
// run is refused only when it would write too many rows (D11).
TEST(CliFiles, SummaryOnlyRunSamplesNothingAndHugeOutputsAreRefused) {
  CliSandbox box;
  CliResult r = box.run({"simulate", "--periods", "100000"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = json::parse(r.out);
  EXPECT_TRUE(s["stick_fraction"].is_null());
  EXPECT_EQ(s["final"]["t"], 100000.0);
  expect_one_line_error(box.run({"simulate", "--periods", "100000", "--out", "big.csv"}),
                        {"output_step", "1e7"});
  expect_one_line_error(box.run({"simulate", "--output-step", "1e-12", "--out", "big.csv"}),
                        {"output_step"});
  expect_one_line_error(box.run({"simulate", "--periods", "1e9"}), {"periods", "1e8"});
  expect_one_line_error(
      box.run({"simulate", "--method", "time-stepping", "--step", "10", "--periods", "1"}),
      {"step = 10", "period"});  // D14
  EXPECT_TRUE(box.work_entries().empty());
}

// D07, D17: errors in a samples file name the file (not an internal "accelerations"), and a
// first data row with a number out of range is an error, not a dropped "header".
TEST(CliFiles, SamplesErrorsNameTheFileAndTheLine) {
  CliSandbox box;
  write_text(box.work_file("drift.csv"), "t,ydd\n0,1\n0.5,1\n1,1\n");
  expect_one_line_error(box.run({"simulate", "--profile", "samples", "--samples", "drift.csv"}),
                        {"samples = drift.csv", "integrate to 0"});
  write_text(box.work_file("range.csv"), "0,1e400\n0,1\n0.5,-1\n1,0\n");
  expect_one_line_error(box.run({"steady", "--profile", "samples", "--samples", "range.csv"}),
                        {"range.csv line 1", "beyond the range"});
  write_text(box.work_file("long.csv"), "t,ydd\n0,1\n5e299,-1\n1e300,0\n");
  expect_one_line_error(box.run({"simulate", "--profile", "samples", "--samples", "long.csv",
                                 "--out", "run.csv"}),
                        {"samples = long.csv", "1e50"});  // D13: no NaN rows written
  // A denormal period (fuzz seed 8): its samples' spacing P/N rounded to 0, an endless loop.
  write_text(box.work_file("tiny.csv"), "0,1\n5e-324,-1\n1e-323,0\n");
  expect_one_line_error(box.run({"converge", "--profile", "samples", "--samples", "tiny.csv"}),
                        {"samples = tiny.csv", "period", "1e-50"});
  EXPECT_EQ(box.work_entries(),
            (std::vector<std::string>{"drift.csv", "long.csv", "range.csv", "tiny.csv"}));
}

#endif  // SELFALIGN_CLI_PATH
