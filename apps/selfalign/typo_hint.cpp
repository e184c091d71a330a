#include "typo_hint.hpp"

#include <string_view>
#include <vector>

#include "selfalign/io/simulate_config.hpp"
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

// "selfalign sweep accelerations": the command path of `app`.
std::string command_path(const CLI::App* app) {
  std::string path = app->get_name();
  for (const CLI::App* up = app->get_parent(); up; up = up->get_parent())
    path = up->get_name() + " " + path;
  return path;
}

// The flag of the config key `name` names ("c_mu" and "c-mu" both name --c-mu), or "".
std::string config_key_flag(std::string name) {
  for (char& c : name)
    if (c == '_') c = '-';
  for (const ConfigKey& k : simulate_config_keys())
    if (config_flag(k) == "--" + name) return "--" + name;
  return {};
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
      const std::string key_flag = config_key_flag(name);
      if (!key_flag.empty() && !at->get_option_no_throw(key_flag))  // a key it does not read
        return key_flag + " is not used by " + command_path(at) +
               " (a --config file may hold the key; it is ignored there)";
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
