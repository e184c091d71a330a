#include "feeder_config.hpp"

#include <cmath>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/io/config_reader.hpp"
#include "selfalign/io/document.hpp"

namespace selfalign::cli {
namespace {

const DocumentKind kFeederDocument{"config", "--config", 2};

ValueType type_of(const FeederConfigKey& k) {
  return std::holds_alternative<std::string*>(k.target) ? ValueType::text : ValueType::number;
}

}  // namespace

void apply_feeder_config(const std::string& path, const CLI::App& command,
                         const std::vector<FeederConfigKey>& keys) {
  std::vector<KeySpec> specs;
  specs.reserve(keys.size());
  for (const FeederConfigKey& k : keys) specs.push_back({k.section, k.name, type_of(k)});
  const KeyTable table{specs, "docs/feeder.md"};
  const nlohmann::json doc = read_document(path, kFeederDocument);
  const ConfigValues values = read_config_values(doc, table, path);
  for (const FeederConfigKey& k : keys) {
    const ConfigValue* v = values.find(k.section, k.name);
    if (!v || command.get_option(std::string(k.flag))->count() > 0) continue;
    std::visit(
        [&](auto* target) {
          using T = std::remove_pointer_t<decltype(target)>;
          if constexpr (std::is_same_v<T, std::string>) {
            *target = std::get<std::string>(*v);
          } else if constexpr (std::is_same_v<T, long long>) {
            const double d = std::get<double>(*v);
            if (!(std::isfinite(d) && d == std::round(d) && std::abs(d) <= 1e15))
              throw InvalidParameter(qualified_key(k.section, k.name), d,
                                     "must be a whole number (in " + path + ")");
            *target = static_cast<long long>(d);
          } else {
            *target = std::get<double>(*v);
          }
        },
        k.target);
    if (k.given) *k.given = true;
  }
}

}  // namespace selfalign::cli
