#pragma once
/// \file atomic_file.hpp
/// Writing output files so that a reader (or a failed run) never sees a partial file, and an
/// input is never overwritten.
///
/// Each file is first written in full to a temporary file in the target's directory
/// ("<path>.tmp-XXXXXX"), flushed to disk and closed; only then is it renamed onto the target
/// (rename(2) is atomic within one file system). AtomicFileSet extends this to several files:
/// every temporary is written first, and the renames happen only once all writes succeeded, so
/// a run that fails while writing leaves none of its new output files behind.
///
/// What a target path may be:
///  - a new or existing regular file: replaced atomically, keeping an existing file's mode;
///  - a symbolic link: the file it points to is replaced (the link stays);
///  - a FIFO, character device or socket (e.g. /dev/null, a named pipe): written directly at
///    commit, never replaced;
///  - "-": standard output, written at commit after the files;
///  - not a directory, not an input of the run and not the file of another output of the run
///    (require_output_path, run_files.hpp): these throw InvalidParameter before anything is
///    written.

#include <string>
#include <string_view>
#include <vector>

#include "selfalign/io/run_files.hpp"  // require_output_path, register_input_file

namespace selfalign {

/// A group of files committed together. Temporaries not committed are removed by the
/// destructor (and by the signal handlers of remove_temporaries_on_signals). Not copyable.
class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;
  ~AtomicFileSet();

  /// Writes content to a fresh temporary beside path (or keeps it for a FIFO/device or "-").
  /// `name` is the parameter that chose the path (e.g. "out"), used in messages. Throws
  /// InvalidParameter(name, path, <reason>) when path is not a valid output (see
  /// require_output_path, which registers it), was already added (under any spelling), or
  /// cannot be created or written.
  void add(const std::string& path, std::string_view content, const std::string& name);

  /// Renames every temporary onto its target, in the order added, then writes the FIFOs,
  /// devices and standard output. When a rename fails, the temporaries left are removed and
  /// the targets this set had created are removed again (files it replaced stay replaced:
  /// each is complete); throws InvalidParameter naming the file.
  void commit();

 private:
  struct Pending {
    std::string name;       // the parameter, for messages
    std::string path;       // as given
    std::string target;     // the file to replace (links resolved), or the FIFO/device
    std::string temporary;  // empty: written directly at commit (FIFO, device, stdout)
    std::string content;    // FIFO, device or stdout only
    bool existed = false;   // the target existed before commit
    bool stream = false;    // a FIFO, device or socket: written directly
    bool to_stdout = false;
  };
  std::vector<Pending> pending_;
};

/// Writes one file atomically (an AtomicFileSet of one).
void write_file_atomically(const std::string& path, std::string_view content,
                           const std::string& name);

/// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGPIPE that remove every temporary of
/// every live AtomicFileSet, then end the process with the signal's default action (so the
/// exit status still says which signal). For programs (the CLI); idempotent.
void remove_temporaries_on_signals();

}  // namespace selfalign
