// Shell completion and the man page (hidden `selfalign completion bash|zsh`, `selfalign man`):
// generated from the same tree as --help, so every subcommand and flag --help lists is there,
// and bash completes them. (zsh is not installed on the build machines: its script is checked
// for the same names, and parsed by zsh where zsh exists.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
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

// What bash completes for each list of words (the last is being completed), in one bash run of
// the script: one line per query.
std::vector<std::string> complete(const CliSandbox& box, const std::string& script,
                                  const std::vector<std::vector<std::string>>& queries) {
  std::string shell = "source " + quote(script) + "\n";
  for (const auto& words : queries) {
    std::string array;
    for (const std::string& w : words) array += " " + quote(w);
    shell += "COMP_WORDS=(selfalign" + array + "); COMP_CWORD=" + std::to_string(words.size()) +
             "; COMPREPLY=(); _selfalign; echo \"${COMPREPLY[*]}\"\n";
  }
  const std::string file = box.file("queries.sh"), out = box.file("completion.txt");
  std::ofstream(file) << shell;
  const std::string cmd =
      "cd " + quote(box.work().string()) + " && bash " + quote(file) + " > " + quote(out);
  EXPECT_EQ(std::system(cmd.c_str()), 0);
  return lines(read_text(out));
}

TEST(CliCompletion, BashZshAndManListEverySubcommandAndFlagOfHelp) {
  CliSandbox box;
  std::map<std::string, std::set<std::string>> flags;
  for (const std::string& command : kCommands) flags[command] = help_flags(box, command);

  const std::string script = box.file("selfalign.bash");
  const auto r = box.run({"completion", "bash", "--out", script});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::vector<std::string>> queries = {
      {"des"}, {"sweep", "acc"}, {"planar", "st"}, {"simulate", "--c-"},
      {"simulate", "--a2", "3", "--c-"},
      {"steady", "--config", ""}};  // after a FILE flag, files: the work folder holds none
  for (const std::string& command : kCommands) {
    queries.push_back(split(command));
    queries.back().push_back("--");
  }
  const std::vector<std::string> got = complete(box, script, queries);
  ASSERT_EQ(got.size(), queries.size());
  EXPECT_EQ(got[0], "design");
  EXPECT_EQ(got[1], "accelerations");
  EXPECT_EQ(got[2], "steady stop");
  EXPECT_EQ(got[3], "--c-mu");
  EXPECT_EQ(got[4], "--c-mu");
  EXPECT_EQ(got[5], "");
  for (std::size_t i = 0; i < kCommands.size(); ++i) {
    const std::vector<std::string> offered = split(got[6 + i]);
    for (const std::string& f : flags[kCommands[i]])
      EXPECT_NE(std::find(offered.begin(), offered.end(), f), offered.end())
          << kCommands[i] << " " << f;
  }

  const auto zsh = box.run({"completion", "zsh"});
  ASSERT_EQ(zsh.exit_code, 0) << zsh.err;
  EXPECT_EQ(zsh.out.rfind("#compdef selfalign\n", 0), 0u);
  const auto man = box.run({"man"});
  ASSERT_EQ(man.exit_code, 0) << man.err;
  EXPECT_EQ(man.out.rfind(".TH SELFALIGN 1", 0), 0u);
  EXPECT_TRUE(std::none_of(man.out.begin(), man.out.end(), [](char c) { return c & 0x80; }))
      << "the page is ASCII";
  for (const std::string& command : kCommands) {
    EXPECT_NE(man.out.find(".SS \"selfalign " + command + "\""), std::string::npos) << command;
    for (const std::string& f : flags[command]) {
      std::string roff;  // dashes are \- in roff
      for (char c : f) roff += c == '-' ? std::string("\\-") : std::string(1, c);
      EXPECT_NE(man.out.find("\\fB" + roff + "\\fR"), std::string::npos) << command << " " << f;
      EXPECT_TRUE(std::regex_search(zsh.out, std::regex("[ \"]" + f + "[ \"]")))
          << command << " " << f;
    }
  }
  if (std::system("command -v zsh > /dev/null 2>&1") == 0) {
    std::ofstream(box.file("_selfalign")) << zsh.out;
    EXPECT_EQ(std::system(("zsh -n " + quote(box.file("_selfalign"))).c_str()), 0);
  }
  // Bad use of the hidden commands is one error line, like every other.
  const auto bad = box.run({"completion", "fish"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("invalid shell = fish: must be bash or zsh"), std::string::npos)
      << bad.err;
}

}  // namespace
}  // namespace selfalign
#endif  // SELFALIGN_CLI_PATH
