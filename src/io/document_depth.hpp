#pragma once
// Internal to io/document.cpp: where a JSON or TOML text first nests deeper than a limit, found
// by a scan of its characters before any recursive code (toml++'s parser, the destructors of
// its tree, a conversion) sees it.

#include <cstddef>
#include <string_view>

namespace selfalign::detail {

/// The byte at which `text` (JSON) first opens an object or array nested deeper than
/// `max_depth` (the top level counts 1), or text.size() if nowhere. Exact for valid JSON.
std::size_t json_too_deep_at(std::string_view text, int max_depth);

/// The same for TOML, counting the tables and arrays as the text writes them: the root (1), the
/// tables of a header ([a.b] makes two; [[a]] an array and its table), of a dotted key
/// (a.b.c = 1 makes two), arrays and inline tables. A bound, not the exact depth: a header
/// under an array of tables written earlier ([[a]] then [a.b]) is a level deeper per such
/// array than counted, so a document this scan accepts nests at most twice `max_depth`; the
/// exact limit is checked on the parsed tree. An invalid document may be refused here before
/// the parser would name its error.
std::size_t toml_too_deep_at(std::string_view text, int max_depth);

}  // namespace selfalign::detail
