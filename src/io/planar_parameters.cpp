// The named parameter view of a planar config (planar_config.hpp): the numbers the setup was
// built from (ConfigSection's read log), less the settings, one parameter per number and per
// array element.

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "selfalign/io/planar_config.hpp"

namespace selfalign {
namespace {

// The unit of element i of `key` as the config gives it: the key's SI unit ("[m]"; one per
// component: "[m, m, rad]") in an SI config; in a dimensionless one "[-]", angles "[rad]".
std::string element_unit(const KeySpec& key, std::size_t i, bool si) {
  std::string_view unit = key.unit;
  if (!key.components.empty() && unit.size() > 2 && unit.front() == '[') {
    std::vector<std::string_view> parts;  // "[m, m, rad]" -> m, m, rad
    std::string_view inner = unit.substr(1, unit.size() - 2);
    for (std::size_t begin = 0; begin <= inner.size();) {
      const std::size_t end = std::min(inner.find(", ", begin), inner.size());
      parts.push_back(inner.substr(begin, end - begin));
      begin = end + 2;
    }
    if (parts.size() == key.components.size()) {
      const std::string part = "[" + std::string(parts[i]) + "]";
      return si || part == "[rad]" ? part : "[-]";
    }
  }
  const std::string whole(unit.empty() ? "[-]" : unit);
  return si || whole == "[rad]" ? whole : "[-]";
}

}  // namespace

std::vector<ModelParameter> planar_model_parameters(const std::string& path,
                                                    const std::vector<std::string>& set) {
  std::vector<ConfigSection::Read> reads;
  const PlanarSetup setup = load_planar_config(path, set, &reads);
  return planar_model_parameters(reads, setup.si);
}

std::vector<ModelParameter> planar_model_parameters(const std::vector<ConfigSection::Read>& reads,
                                                    bool si) {
  std::vector<ModelParameter> out;
  std::vector<const KeySpec*> listed;  // a key read twice is listed once
  for (const ConfigSection::Read& r : reads) {
    const KeySpec& key = *r.key;
    if (key.role != KeyRole::parameter ||
        std::find(listed.begin(), listed.end(), &key) != listed.end())
      continue;
    listed.push_back(&key);
    const std::string name = qualified_key(key.section, key.name);
    const bool array = key.type == ValueType::numbers;
    for (std::size_t i = 0; i < r.values.size(); ++i) {
      const Dimension d = key.components.empty() ? key.dimension : key.components[i];
      out.push_back({array ? name + "[" + std::to_string(i) + "]" : name, r.values[i], d,
                     element_unit(key, i, si), std::string(key.section),
                     std::string(key.help)});
    }
  }
  return out;
}

}  // namespace selfalign
