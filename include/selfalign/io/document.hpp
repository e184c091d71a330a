#pragma once
/// \file document.hpp
/// The one reader of JSON and TOML input documents: the simulate config (--config), the planar
/// config, the uncertainty file and the design report (montecarlo --design). Each is read into
/// a JSON tree that its own module then interprets key by key.
///
/// What every document gets, whatever its kind:
///  - the path checked and registered as an input of the run (require_input_file,
///    run_files.hpp): a regular file of at most kMaxDocumentBytes; the format by extension
///    (.json or .toml);
///  - a nesting limit (the kind's max_depth) applied before any recursive code sees the
///    document: JSON through a SAX builder that stops at the first container too deep
///    (nlohmann's parser is iterative; the tree it would build is what recursive code, dump()
///    included, later walks), TOML by a scan of its text before toml++ (whose parser and tree
///    are recursive) reads it, counting the tables that headers and dotted keys create (a
///    bound within twice the limit), then exactly on the tree it returns;
///  - one clean error line: InvalidParameter(kind.name, path, "<what> at line L, column C"),
///    the library's wording reduced to what is wrong (no "[json.exception...]", no macro names).
///
/// TOML values map to JSON ones: tables to objects, arrays to arrays, integers and floats to
/// numbers (nan and inf kept as doubles), booleans, strings; dates and times to their text.

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace selfalign {

/// The largest input document read (16 MB): a config is a few hundred bytes, a design report a
/// few kilobytes.
inline constexpr std::uintmax_t kMaxDocumentBytes = std::uintmax_t{16} << 20;

/// What a document is: how messages name it and how deep it may nest.
struct DocumentKind {
  std::string name;  ///< the parameter in messages, e.g. "config file", "uncertainty-file"
  std::string flag;  ///< the flag that gives it, e.g. "--config" (registered as the input's flag)
  int max_depth;     ///< tables/objects and arrays nested, the top-level table counting 1
};

/// Reads `path` as a document of `kind`. Throws InvalidParameter(kind.name, path, ...) for an
/// empty path, a folder, a FIFO or device, a file over kMaxDocumentBytes, an extension other
/// than .json / .toml, an unreadable or malformed file, and nesting deeper than
/// kind.max_depth; the message says where (line, column) and what is wrong.
nlohmann::json read_document(const std::string& path, const DocumentKind& kind);

/// `value` as message text: a JSON dump of at most 60 characters (longer: cut, with "..."),
/// for naming a wrong-typed value in one short error line.
std::string document_value_text(const nlohmann::json& value);

}  // namespace selfalign
