#include "typo_hint.hpp"

#include <string_view>
#include <vector>

#include "selfalign/io/spelling.hpp"

namespace selfalign::cli {
namespace {

// Flags that were replaced, and by what (their old meaning is not accepted silently).
struct Retired {
  std::string_view flag, replacement;
};
constexpr Retired kRetired[] = {
    {"static-ratio", "--mu-static, an absolute coefficient with --mu (ratio = mu-static/mu)"},
    {"backward-ratio", "--mu-backward, an absolute coefficient with --mu"},
};

// The subcommand the parse reached: the deepest one parsed.
CLI::App* reached(CLI::App* app) {
  for (;;) {
    const std::vector<CLI::App*> parsed = app->get_subcommands();
    if (parsed.empty()) return app;
    app = parsed.front();
  }
}

std::vector<std::string> flag_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& n : o->get_lnames()) names.push_back(n);
  return names;
}

std::vector<std::string> subcommand_names(CLI::App& app) {
  std::vector<std::string> names;
  for (CLI::App* sub : app.get_subcommands({}))
    if (!sub->get_group().empty()) names.push_back(sub->get_name());  // hidden ones excluded
  return names;
}

}  // namespace

std::string typo_hint(CLI::App& app, int argc, const char* const* argv) {
  CLI::App* at = reached(&app);
  const bool takes_subcommand = !subcommand_names(*at).empty();
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word.size() > 2 && word.substr(0, 2) == "--") {
      const std::string name(word.substr(2, word.find('=') - 2));
      if (at->get_option_no_throw("--" + name)) continue;
      for (const Retired& r : kRetired)
        if (name == r.flag)
          return "unknown flag --" + name + " (replaced by " + std::string(r.replacement) + ")";
      const std::string best = closest_name(name, flag_names(*at));
      if (!best.empty()) return "unknown flag --" + name + " (did you mean --" + best + "?)";
    } else if (takes_subcommand && !word.empty() && word[0] != '-') {
      const std::string best = closest_name(word, subcommand_names(*at));
      if (!best.empty() && best != word)
        return "unknown subcommand " + std::string(word) + " (did you mean " + best + "?)";
    }
  }
  return {};
}

}  // namespace selfalign::cli
