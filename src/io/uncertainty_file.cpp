#include "selfalign/io/uncertainty_file.hpp"

#include "selfalign/error.hpp"
#include "selfalign/io/document.hpp"

namespace selfalign {
namespace {

// One table of NAME = "DIST" pairs; a second level lets a wrong-typed value (an array) be
// named as such rather than as nesting.
const DocumentKind kUncertaintyDocument{"uncertainty-file", "--uncertainty-file", 2};

}  // namespace

ProcessUncertainty load_uncertainty(const std::string& path) {
  const nlohmann::json doc = read_document(path, kUncertaintyDocument);
  if (!doc.is_object())
    throw InvalidParameter("uncertainty-file", path, "must be a table of input = \"distribution\"");
  ProcessUncertainty u;
  for (const auto& [name, value] : doc.items()) {
    if (!value.is_string())
      throw InvalidParameter(name, document_value_text(value),
                             "must be a distribution string, e.g. \"normal:0.2,5%\" (in " +
                                 path + ")");
    set_input(u, name, value.get<std::string>());
  }
  validate(u);
  return u;
}

}  // namespace selfalign
