#include "selfalign/io/uncertainty_file.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

ProcessUncertainty load_uncertainty(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidParameter("uncertainty-file", path, "must be a readable file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  ProcessUncertainty u;
  const auto malformed = [&](const std::string& why) {
    return InvalidParameter("uncertainty-file", path, why);
  };
  if (ends_with(path, ".json")) {
    nlohmann::json doc;
    try {
      doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      throw malformed("must be valid JSON (" + std::string(e.what()) + ")");
    }
    if (!doc.is_object()) throw malformed("must be a JSON object of input: distribution");
    for (const auto& [name, value] : doc.items()) {
      if (!value.is_string())
        throw InvalidParameter(name, value.dump(), "must be a distribution string, e.g. \"normal:0.2,5%\"");
      set_input(u, name, value.get<std::string>());
    }
  } else if (ends_with(path, ".toml")) {
    toml::table doc;
    try {
      doc = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
      throw malformed("must be valid TOML (" + std::string(e.description()) + ")");
    }
    for (const auto& [name, node] : doc) {
      const auto* value = node.as_string();
      if (!value)
        throw InvalidParameter(std::string(name.str()), "not a string",
                               "must be a distribution string, e.g. \"normal:0.2,5%\"");
      set_input(u, std::string(name.str()), value->get());
    }
  } else {
    throw malformed("must end in .json or .toml");
  }
  validate(u);
  return u;
}

}  // namespace selfalign
