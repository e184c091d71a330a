#pragma once

#include <gtest/gtest.h>
// Running the real `selfalign` binary (SELFALIGN_CLI_PATH) in a fresh temporary directory, for
// the CLI tests (test_cli.cpp, test_cli_analysis.cpp): exit code, captured stdout and stderr,
// and the files a run left behind.

#ifdef SELFALIGN_CLI_PATH

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "selfalign/error.hpp"
#include "temp_dir.hpp"

namespace selfalign::testing {

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

/// The binary under test: SELFALIGN_CLI_PATH, or $SELFALIGN_TEST_CLI when set (a test run
/// against another build, e.g. to see a regression test fail before its fix).
inline std::string cli_path() {
  const char* other = std::getenv("SELFALIGN_TEST_CLI");
  return other && *other ? other : SELFALIGN_CLI_PATH;
}

/// `s` single-quoted for the shell.
inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// A temporary root; the CLI runs in root/work (which must hold only the run's outputs), and
/// config files and the captured stdout / stderr live in root.
class CliSandbox {
 public:
  CliSandbox() { std::filesystem::create_directory(work()); }
  std::filesystem::path work() const { return root_.path() / "work"; }
  std::string file(const std::string& name) const { return root_.file(name); }
  std::string work_file(const std::string& name) const { return (work() / name).string(); }

  CliResult run(const std::vector<std::string>& args) const {
    std::string command = "cd " + quote(work().string()) + " && " + quote(cli_path());
    for (const std::string& a : args) command += " " + quote(a);
    command += " >" + quote(file("stdout.txt")) + " 2>" + quote(file("stderr.txt"));
    const int status = std::system(command.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_text(file("stdout.txt"));
    r.err = read_text(file("stderr.txt"));
    return r;
  }

  std::vector<std::string> work_entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(work()))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  TempDir root_;
};

/// The lines of `text`, without their newlines.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

/// The contract for bad input: exit code 2, exactly one line `selfalign: error: ...` on stderr
/// containing every `expected` substring (the parameter's name and its allowed range), nothing
/// on stdout, and no file left in the sandbox's work folder.
inline void expect_clean_failure(const CliSandbox& box, const CliResult& r,
                                 const std::vector<std::string>& expected) {
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.back(), '\n');
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("selfalign: error: ", 0), 0u) << r.err;
  for (const std::string& s : expected) EXPECT_NE(r.err.find(s), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(box.work_entries().empty()) << "left behind: " << box.work_entries().front();
}

/// The contract for bad input where the work folder may hold the run's inputs: exit code 2,
/// exactly one line `selfalign: error: ...` containing every `expected` substring, nothing on
/// stdout (the caller checks the folder).
inline void expect_one_line_error(const CliResult& r, const std::vector<std::string>& expected) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("selfalign: error: ", 0), 0u) << r.err;
  for (const std::string& s : expected) EXPECT_NE(r.err.find(s), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

/// A parameterised misuse case: the command line and what its error line must contain.
struct MisuseCase {
  std::string name;
  std::vector<std::string> args;
  std::vector<std::string> expected;  // substrings of the error line
};

inline void PrintTo(const MisuseCase& c, std::ostream* os) { *os << c.name; }

/// SI results against dimensionless ones converted: a handful of roundings per conversion
/// and the shortest round-trip text of the numbers (1e-9 leaves wide headroom).
inline constexpr double kSiAgreement = 1e-9;

/// Column `column` of a CSV row, as text and as a number.
inline std::string csv_text(const std::string& row, int column) {
  std::size_t begin = 0;
  for (int i = 0; i < column; ++i) begin = row.find(',', begin) + 1;
  return row.substr(begin, row.find(',', begin) - begin);
}
inline double csv_field(const std::string& row, int column) {
  return std::stod(csv_text(row, column));
}

/// A number as the CLI prints it (shortest round-trip text).
inline std::string num(double v) { return format_number(v); }

}  // namespace selfalign::testing

#endif  // SELFALIGN_CLI_PATH
