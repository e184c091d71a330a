#pragma once
/// \file atomic_file.hpp
/// Writing output files so that a reader (or a failed run) never sees a partial file.
///
/// Each file is first written in full to a temporary file in the target's directory
/// ("<path>.tmp-XXXXXX"), flushed to disk and closed; only then is it renamed onto the target
/// (rename(2) is atomic within one file system). AtomicFileSet extends this to several files:
/// every temporary is written first, and the renames happen only once all writes succeeded, so
/// a run that fails while writing leaves none of its output files behind.

#include <string>
#include <string_view>
#include <vector>

namespace selfalign {

/// A group of files committed together. Temporaries not committed are removed by the
/// destructor. Not copyable.
class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;
  ~AtomicFileSet();

  /// Writes content to a fresh temporary beside path. Throws InvalidParameter("output file",
  /// path, <reason>) when it cannot be created or written, or when path was already added.
  void add(const std::string& path, std::string_view content);

  /// Renames every temporary onto its target, in the order added. Throws InvalidParameter
  /// naming the file on failure; the temporaries not yet renamed are then removed (files
  /// renamed before the failure stay: each is complete, but the set is not).
  void commit();

 private:
  struct Pending {
    std::string target, temporary;
  };
  std::vector<Pending> pending_;
};

/// Writes one file atomically (an AtomicFileSet of one).
void write_file_atomically(const std::string& path, std::string_view content);

}  // namespace selfalign
