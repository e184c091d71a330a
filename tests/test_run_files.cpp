// Tests for io/run_files.hpp: files compared by identity, not by spelling (issue 20, D24, D25):
// an output is never an input nor another output's file, whichever is registered first and
// however either is spelled (./x, sub/../x, a symbolic or hard link).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/run_files.hpp"
#include "temp_dir.hpp"

using namespace selfalign;
using namespace selfalign::testing;
namespace fs = std::filesystem;

namespace {

// The message of the InvalidParameter that `f` throws ("" when it throws none).
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const InvalidParameter& e) {
    return e.what();
  }
  return "";
}

// A fresh registry and a folder with x (a file), sub/ (a folder), a link and a hard link to x.
class RunFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    forget_run_files();
    write_text(dir.file("x"), "input\n");
    fs::create_directory(dir.file("sub"));
    fs::create_symlink("x", dir.file("link"));
    fs::create_hard_link(dir.file("x"), dir.file("hard"));
  }
  void TearDown() override { forget_run_files(); }
  std::string at(const std::string& name) const { return dir.file(name); }
  TempDir dir;
};

TEST_F(RunFilesTest, EverySpellingOfOneFileIsThatFile) {
  for (const char* alias : {"x", "./x", "sub/../x", "sub/./../x", "link", "hard"})
    EXPECT_TRUE(same_file(at("x"), at(alias))) << alias;
  EXPECT_FALSE(same_file(at("x"), at("sub")));
  // Files not created yet: by their folder and name.
  EXPECT_TRUE(same_file(at("new.csv"), at("./new.csv")));
  EXPECT_TRUE(same_file(at("new.csv"), at("sub/../new.csv")));
  EXPECT_FALSE(same_file(at("new.csv"), at("sub/new.csv")));
  // A dangling link names the file a write through it would create.
  fs::create_symlink("made.csv", at("dangling"));
  EXPECT_TRUE(same_file(at("dangling"), at("./made.csv")));
}

TEST_F(RunFilesTest, AnOutputIsNeverAnInputWhicheverComesFirst) {
  register_input_file(at("x"), "--design");
  for (const char* alias : {"x", "./x", "sub/../x", "link", "hard"}) {
    const std::string m = refusal([&] { require_output_path("out", at(alias)); });
    EXPECT_NE(m.find("invalid out = "), std::string::npos) << alias << ": " << m;
    EXPECT_NE(m.find("given as --design"), std::string::npos) << m;
  }
  forget_run_files();
  require_output_path("runs-csv", at("sub/../x"));  // the output first: the input is refused
  const std::string m = refusal([&] { register_input_file(at("link"), "--uncertainty-file"); });
  EXPECT_NE(m.find("invalid runs-csv = "), std::string::npos) << m;
  EXPECT_NE(m.find("given as --uncertainty-file"), std::string::npos) << m;
  EXPECT_EQ(read_text(at("x")), "input\n");
}

TEST_F(RunFilesTest, TwoOutputsNeverNameOneFile) {
  require_output_path("out", at("./same.out"));
  std::string m = refusal([&] { require_output_path("profile-csv", at("same.out")); });
  EXPECT_NE(m.find("invalid profile-csv = "), std::string::npos) << m;
  EXPECT_NE(m.find("same file as --out"), std::string::npos) << m;
  m = refusal([&] { require_output_path("csv", at("sub/../same.out")); });
  EXPECT_NE(m.find("same file as --out"), std::string::npos) << m;
  // An output registered again under its name moves (a config's out overridden by a flag).
  require_output_path("out", at("other.out"));
  EXPECT_EQ(refusal([&] { require_output_path("summary", at("same.out")); }), "");
  // Standard output is not a file.
  require_output_path("out", "-");
  EXPECT_EQ(refusal([&] { require_output_path("summary", "-"); }), "");
}

// A registered path stands for the file it names now: replaced by a rename (a new inode), x is
// still the output; deleted, it no longer blocks another file that may reuse its inode.
TEST_F(RunFilesTest, ARegisteredPathIsIdentifiedWhenCompared) {
  require_output_path("out", at("x"));
  write_text(at("y"), "new\n");
  fs::rename(at("y"), at("x"));
  EXPECT_NE(refusal([&] { register_input_file(at("./x"), "--config"); }), "");
  fs::remove(at("x"));
  fs::remove(at("hard"));
  write_text(at("z"), "z\n");
  EXPECT_EQ(refusal([&] { register_input_file(at("z"), "--config"); }), "");
}

TEST_F(RunFilesTest, AtomicFileSetRefusesOneFileTwiceUnderTwoSpellings) {
  AtomicFileSet files;
  files.add(at("a.csv"), "alpha", "out");
  const std::string m = refusal([&] { files.add(at("./a.csv"), "beta", "out"); });
  EXPECT_NE(m.find("written twice"), std::string::npos) << m;
  files.commit();
  EXPECT_EQ(read_text(at("a.csv")), "alpha");
}

}  // namespace
