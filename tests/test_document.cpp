// Tests for io/document.hpp, the one reader of JSON and TOML inputs (issue 20, D23, D31): the
// nesting limit is applied before recursive code sees a document (a 1e5-deep array, dotted key
// or table header ends in one error line, not a stack overflow), errors name the file, the line
// and the column and show no library internals, and the file becomes an input of the run.
//
// Expected depths and positions are counted by hand from the documents below: the top level
// counts 1; each array, object / inline table, header table ([a.b]: two; [[a]]: an array and
// its table) and table of a dotted key (a.b = 1: one) adds 1. A position is the character where
// the parser stopped (nlohmann: the last character it read), columns from 1.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/io/document.hpp"
#include "selfalign/io/run_files.hpp"
#include "temp_dir.hpp"

using namespace selfalign;
using namespace selfalign::testing;

namespace {

const DocumentKind kTwoLevels{"uncertainty-file", "--uncertainty-file", 2};

class DocumentTest : public ::testing::Test {
 protected:
  void SetUp() override { forget_run_files(); }
  void TearDown() override { forget_run_files(); }

  // Reads `text` as <name>; "" when accepted, else the error message.
  std::string read(const std::string& name, const std::string& text,
                   const DocumentKind& kind = kTwoLevels) {
    write_text(dir.file(name), text);
    try {
      read_document(dir.file(name), kind);
    } catch (const InvalidParameter& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_EQ(m.find("json.exception"), std::string::npos) << m;
      EXPECT_EQ(m.find("TOML_"), std::string::npos) << m;
      EXPECT_NE(m.find(name), std::string::npos) << m;  // the file
      return m;
    }
    return "";
  }
  // Refused for nesting, at `where`.
  void expect_too_deep(const std::string& name, const std::string& text, const std::string& where,
                       const DocumentKind& kind = kTwoLevels) {
    const std::string m = read(name, text, kind);
    EXPECT_NE(m.find("nests too deeply at " + where + ":"), std::string::npos) << name << ": " << m;
  }
  TempDir dir;
};

TEST_F(DocumentTest, JsonNestingIsLimitedBeforeItIsBuilt) {
  EXPECT_EQ(read("a.json", R"({"mu": "normal:0.2,5%", "a": [1, 2]})"), "");
  expect_too_deep("b.json", R"({"a": [[1]]})", "line 1, column 8");
  expect_too_deep("c.json", "{\n  \"a\":\n    [[1]]\n}", "line 3, column 6");
  // Brackets in strings (escaped quotes too) are text.
  EXPECT_EQ(read("d.json", R"({"a": "[[[{{", "b": ["\"]]]{{[["]})"), "");
  const int deep = 100000;  // D23: this overflowed the stack
  expect_too_deep("e.json", "{\"mu\": " + std::string(deep, '[') + std::string(deep, ']') + "}",
                  "line 1, column 9");
  // A report's depth: 5 levels accepted under a limit of 5, 6 refused.
  const DocumentKind five{"design", "--design", 5};
  EXPECT_EQ(read("f.json", R"({"r": {"v": {"h": {"e": [1]}}}})", five), "");
  expect_too_deep("g.json", R"({"r": {"v": {"h": {"e": [[1]]}}}})", "line 1, column 26", five);
}

TEST_F(DocumentTest, TomlNestingIsLimitedBeforeTheParserSeesIt) {
  EXPECT_EQ(read("a.toml", "mu = \"normal:0.2,5%\"\na = [1, 2]\nb.c = 1\n[t]\nx = 1\n"), "");
  expect_too_deep("b.toml", "a = [[1]]\n", "line 1, column 6");
  expect_too_deep("c.toml", "a.b.c = 1\n", "line 1, column 4");             // dotted key
  expect_too_deep("d.toml", "x = 1\n[t.u]\ny = 2\n", "line 2, column 1");     // header
  expect_too_deep("e.toml", "[[t]]\ny = 2\n", "line 1, column 1");            // array of tables
  expect_too_deep("f.toml", "[t]\nx = [1]\n", "line 2, column 5");           // array in a table
  expect_too_deep("g.toml", "a = {b = {c = 1}}\n", "line 1, column 10");     // inline tables
  expect_too_deep("h.toml", "a = {b.c = 1}\n", "line 1, column 7");          // dotted, inline
  // Strings, quoted keys, comments and numbers are not nesting.
  EXPECT_EQ(read("i.toml",
                 "a = \"[[[.{\"\n'b.c.d' = 1\nc = \"\"\"\n[[[ x.y.z\n\"\"\"\nd = '''x.y[['''\n"
                 "# [[[ a.b.c\ne = 1.5 # x.y\nf = 1979-05-27T07:32:00Z\ng = {}\n"),
            "");
  // D23: a 1e5-part dotted key, header or nested inline table overflowed toml++'s stack.
  const int deep = 100000;
  std::string key = "a", header = "[a";
  for (int i = 0; i < deep; ++i) key += ".a", header += ".a";
  expect_too_deep("j.toml", key + " = 1\n", "line 1, column 4");
  expect_too_deep("k.toml", header + "]\n", "line 1, column 1");
  std::string inline_tables = "a = ";
  for (int i = 0; i < 300; ++i) inline_tables += "{b = ";
  expect_too_deep("l.toml", inline_tables + "1" + std::string(300, '}') + "\n", "line 1, column 10");
  // A planar config's depth (docs/planar.md): [table.x] cos = [...], [stop] entries = [[...]].
  const DocumentKind four{"config", "--config", 4};
  EXPECT_EQ(read("m.toml", "[table.x]\ncos = [1, 2]\n[stop]\nentries = [[0, 0, 0]]\n", four), "");
  expect_too_deep("n.toml", "[stop]\nentries = [[[0]]]\n", "line 2, column 13", four);
  // A header under an array of tables is a level deeper than it is written ([[a]], then [a.b]
  // is root, array a, its last table, b): found on the parsed tree.
  EXPECT_EQ(read("o.toml", "[[a]]\n[a.b]\nx = 1\n", four), "");
  expect_too_deep("p.toml", "[[a]]\n[a.b]\nx = [1]\n", "line 3, column 5", four);
}

TEST_F(DocumentTest, ErrorsNameFileLineAndColumnWithoutLibraryInternals) {
  std::string m = read("a.json", R"({"units": 0x10})");  // stopped at the x
  EXPECT_NE(m.find("invalid uncertainty-file = "), std::string::npos) << m;
  EXPECT_NE(m.find("is not valid JSON at line 1, column 12:"), std::string::npos) << m;
  // D31: a number overflow had neither the file nor the place.
  m = read("b.json", "{\"a\":\n 1e999}");
  EXPECT_NE(m.find("is not valid JSON at line 2, column 6: number overflow"), std::string::npos)
      << m;
  m = read("c.json", "\xff\xfe{");  // an invalid byte is shown, not echoed
  EXPECT_NE(m.find("line 1, column 1"), std::string::npos) << m;
  EXPECT_NE(m.find("\\xff"), std::string::npos) << m;
  EXPECT_EQ(m.find('\xff'), std::string::npos) << m;
  m = read("d.toml", "x = 1\nwidth = = 1\n");
  EXPECT_NE(m.find("is not valid TOML at line 2"), std::string::npos) << m;
  m = read("e.yaml", "a: 1\n");
  EXPECT_NE(m.find("must end in .json or .toml"), std::string::npos) << m;
  m = read("f.json", "");
  EXPECT_NE(m.find("is not valid JSON at line 1, column 1"), std::string::npos) << m;
}

TEST_F(DocumentTest, ReadsTomlValuesAsJsonAndRegistersTheInput) {
  write_text(dir.file("v.toml"), "i = 3\nf = nan\ng = -inf\ns = \"x\"\nb = true\na = [1, 2.5]\n");
  const nlohmann::json j = read_document(dir.file("v.toml"), kTwoLevels);
  EXPECT_EQ(j["i"].get<double>(), 3.0);
  EXPECT_TRUE(std::isnan(j["f"].get<double>()));
  EXPECT_EQ(j["g"].get<double>(), -INFINITY);
  EXPECT_EQ(j["s"], "x");
  EXPECT_EQ(j["b"], true);
  EXPECT_EQ(j["a"][1].get<double>(), 2.5);
  EXPECT_EQ(input_file_flag(dir.file("./v.toml")), "--uncertainty-file");
}

}  // namespace
