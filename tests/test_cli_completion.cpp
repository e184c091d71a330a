// Shell completion and the man page (hidden `selfalign completion bash|zsh`, `selfalign man`):
// generated from the same tree as --help, so every subcommand and flag --help lists is there,
// and bash completes them. (zsh is not installed on the build machines: its script is checked
// for the same names, and run by zsh where zsh exists.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_sandbox.hpp"

#ifdef SELFALIGN_CLI_PATH
namespace selfalign {
namespace {

using testing::CliSandbox;
using testing::lines;
using testing::quote;
using testing::read_text;

const std::vector<std::string> kCommands = {
    "simulate", "steady", "floquet", "converge", "stop", "accuracy", "accumulation",
    "sweep accelerations", "sweep period", "sweep stroke", "sweep positioning", "optimize",
    "design", "montecarlo", "planar simulate", "planar steady", "planar field", "planar stop"};

std::vector<std::string> split(const std::string& words) {
  std::vector<std::string> out;
  for (std::size_t b = 0, e; b < words.size(); b = e + 1) {
    e = words.find(' ', b);
    if (e == std::string::npos) e = words.size();
    if (e > b) out.push_back(words.substr(b, e - b));
  }
  return out;
}

// The flags `selfalign <command> --help` lists.
std::set<std::string> help_flags(const CliSandbox& box, const std::string& command) {
  std::vector<std::string> args = split(command);
  args.push_back("--help");
  const auto r = box.run(args);
  EXPECT_EQ(r.exit_code, 0) << command;
  std::set<std::string> flags;
  const std::regex flag(R"(^\s+(--[a-z0-9-]+))");
  for (const std::string& line : lines(r.out)) {
    std::smatch m;
    if (std::regex_search(line, m, flag)) flags.insert(m[1]);
  }
  return flags;
}

// What bash completes for the words (the last is being completed), through the script.
std::string complete(const CliSandbox& box, const std::string& script,
                     const std::vector<std::string>& words) {
  std::string array;
  for (const std::string& w : words) array += " " + quote(w);
  const std::string shell = "source " + quote(script) + "; COMP_WORDS=(selfalign" + array +
                            "); COMP_CWORD=" + std::to_string(words.size()) +
                            "; _selfalign; echo \"${COMPREPLY[*]}\"";
  const std::string out = box.file("completion.txt");
  const std::string cmd = "cd " + quote(box.work().string()) + " && bash -c " + quote(shell) +
                          " > " + quote(out) + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << shell;
  const std::string text = read_text(out);
  return text.substr(0, text.find('\n'));
}

TEST(CliCompletion, BashCompletesEverySubcommandAndFlagOfHelp) {
  CliSandbox box;
  const auto r = box.run({"completion", "bash", "--out", box.file("selfalign.bash")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string script = box.file("selfalign.bash");
  EXPECT_EQ(std::system(("bash -n " + quote(script)).c_str()), 0);
  EXPECT_EQ(complete(box, script, {"des"}), "design");
  EXPECT_EQ(complete(box, script, {"sweep", "acc"}), "accelerations");
  EXPECT_EQ(complete(box, script, {"planar", "st"}), "steady stop");
  EXPECT_EQ(complete(box, script, {"steady", "--c-"}), "--c-mu");
  EXPECT_EQ(complete(box, script, {"steady", "--a2", "3", "--c-"}), "--c-mu");
  // After a FILE flag, file names: the sandbox's work folder holds none.
  EXPECT_EQ(complete(box, script, {"steady", "--config", ""}), "");
  // Every flag --help lists, per command (the generator walks the same tree).
  for (const std::string& command : kCommands) {
    std::vector<std::string> words = split(command);
    words.push_back("--");
    std::set<std::string> offered;
    for (const std::string& f : split(complete(box, script, words))) offered.insert(f);
    for (const std::string& f : help_flags(box, command))
      EXPECT_TRUE(offered.count(f)) << command << " " << f;
  }
}

TEST(CliCompletion, ZshScriptAndManPageListTheSameNames) {
  CliSandbox box;
  const auto zsh = box.run({"completion", "zsh"});
  ASSERT_EQ(zsh.exit_code, 0) << zsh.err;
  EXPECT_EQ(zsh.out.rfind("#compdef selfalign\n", 0), 0u);
  const auto man = box.run({"man"});
  ASSERT_EQ(man.exit_code, 0) << man.err;
  EXPECT_EQ(man.out.rfind(".TH SELFALIGN 1", 0), 0u);
  for (const std::string& command : kCommands) {
    EXPECT_NE(man.out.find(".SS \"selfalign " + command + "\""), std::string::npos) << command;
    for (const std::string& f : help_flags(box, command)) {
      std::string roff;  // dashes are \- in roff
      for (char c : f) roff += c == '-' ? std::string("\\-") : std::string(1, c);
      EXPECT_NE(man.out.find("\\fB" + roff + "\\fR"), std::string::npos) << command << " " << f;
      EXPECT_TRUE(std::regex_search(zsh.out, std::regex("[ \"]" + f + "[ \"]")))
          << command << " " << f;
    }
  }
  EXPECT_TRUE(std::none_of(man.out.begin(), man.out.end(), [](char c) { return c & 0x80; }))
      << "the page is ASCII";
  if (std::system("command -v zsh > /dev/null 2>&1") == 0) {
    std::ofstream(box.file("_selfalign")) << zsh.out;
    EXPECT_EQ(std::system(("zsh -n " + quote(box.file("_selfalign"))).c_str()), 0);
  }
  // Bad use of the hidden commands is one error line, like every other.
  const auto bad = box.run({"completion", "fish"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("invalid shell = fish: must be bash or zsh"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace selfalign
#endif  // SELFALIGN_CLI_PATH
