#include "config_flags.hpp"

#include "warnings.hpp"

namespace selfalign::cli {
namespace {

std::string group_title(std::string_view group) {
  if (group == "run") return "Run";
  if (group == "profile") return "Table profile";
  if (group == "friction") return "Friction map";
  if (group == "law") return "Friction law (static, kinetic, Stribeck, viscous)";
  if (group == "scales") return "Scales (SI conversion)";
  if (group == "initial") return "Initial state";
  if (group == "solver") return "Solver";
  return "Output";
}

std::string_view type_name(const ConfigKey& key) {
  switch (key.field.index()) {
    case 0: return key.name == "out" || key.name == "summary" || key.name == "samples" ||
                           key.name == "field_file"
                       ? "FILE"
                                                                                       : "TEXT";
    case 1: return "NUMBER";
    default: return "LIST";
  }
}

const KeyFlag* find_override(const std::vector<KeyFlag>& overrides, std::string_view key) {
  for (const KeyFlag& o : overrides)
    if (o.key == key) return &o;
  return nullptr;
}

template <class List>
bool contains(const List& list, std::string_view x) {
  for (std::string_view y : list)
    if (y == x) return true;
  return false;
}

}  // namespace

std::vector<KeyFlag> without_groups(std::vector<KeyFlag> overrides,
                                    std::initializer_list<std::string_view> groups,
                                    const std::vector<std::string_view>& keep) {
  for (const ConfigKey& k : simulate_config_keys())
    if (contains(groups, k.group) && !contains(keep, k.name) && !find_override(overrides, k.name))
      overrides.push_back({k.name, ""});
  return overrides;
}

std::vector<KeyFlag> without_uniform_table_keys(std::vector<KeyFlag> overrides,
                                                std::vector<std::string_view> keep) {
  if (!contains(keep, "method") && !find_override(overrides, "method"))
    overrides.push_back({"method", ""});
  keep.insert(keep.end(), {"relative_tolerance", "absolute_tolerance"});
  return without_groups(std::move(overrides), {"friction", "initial", "solver"}, keep);
}

std::shared_ptr<ConfigFlags> add_config_flags(CLI::App& command,
                                              const std::vector<KeyFlag>& overrides) {
  auto flags = std::make_shared<ConfigFlags>();
  flags->config_option = command
      .add_option("--config", flags->config_file,
                  "JSON (.json) or TOML (.toml) file of config keys (docs/config.md); flags "
                  "override its values")
      ->type_name("FILE");
  const auto keys = simulate_config_keys();
  flags->values.resize(keys.size());
  flags->options.resize(keys.size(), nullptr);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    std::string help = config_help(keys[i]);
    if (const KeyFlag* o = find_override(overrides, keys[i].name)) {
      if (o->help.empty()) continue;
      help = std::string(o->help);
    }
    flags->options[i] = command.add_option(config_flag(keys[i]), flags->values[i], help)
                            ->type_name(std::string(type_name(keys[i])))
                            ->group(group_title(keys[i].group));
  }
  return flags;
}

SimulateConfig read_config(const ConfigFlags& flags) {
  SimulateConfig config;
  if (flags.config_option && flags.config_option->count() > 0)
    config = load_simulate_config(flags.config_file);  // "" is refused there, not ignored
  const auto keys = simulate_config_keys();
  SimulateConfig overrides;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (flags.options[i] && flags.options[i]->count() > 0)
      set_simulate_config_value(overrides, keys[i].name, flags.values[i]);
  const SimulateConfig given = merge(config, overrides);
  register_config_files(given);  // the samples and field files it names: no output replaces them
  warn_about_config(given);      // printed only if the run succeeds
  return given;
}

}  // namespace selfalign::cli
