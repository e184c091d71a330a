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
///  - not a directory, and not a file this process read as an input (register_input_file):
///    both throw InvalidParameter before anything is written.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace selfalign {

/// Records that this process read `path` as an input given by `flag` (e.g. "--config"); no
/// AtomicFileSet will write over it. Thread-safe.
void register_input_file(const std::string& path, const std::string& flag);

/// Checks that `path` can be read as the input `name`: a non-empty path that, where it exists,
/// is a regular file (a folder is refused, and a FIFO or device, whose read would block or
/// never end) of at most `max_bytes` bytes; then registers it under `flag`
/// (register_input_file). Throws InvalidParameter(name, path, ...). A missing file is left to
/// the reader, which names it.
void require_input_file(const std::string& name, const std::string& path,
                        const std::string& flag, std::uintmax_t max_bytes);

/// The flag of the registered input that `path` names (the same file, also through a link,
/// or the same absolute path), or none.
std::optional<std::string> input_file_flag(const std::string& path);

/// Throws InvalidParameter(name, path, ...) when `path` cannot be an output: empty, a
/// directory, a registered input, or `other_input` (an input not read yet, e.g. the samples
/// file named in a config; may be empty). Called before a run's work so that misuse costs
/// nothing; AtomicFileSet::add checks the same again.
void require_output_path(const std::string& name, const std::string& path,
                         const std::string& other_input = {},
                         const std::string& other_input_flag = {});

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
  /// require_output_path), was already added, or cannot be created or written.
  void add(const std::string& path, std::string_view content, const std::string& name = "out");

  /// Renames every temporary onto its target, in the order added, then writes the FIFOs,
  /// devices and standard output. When a rename fails, the temporaries left are removed and
  /// the targets this set had created are removed again (files it replaced stay replaced:
  /// each is complete); throws InvalidParameter naming the file.
  void commit();

 private:
  struct Pending {
    std::string name;       // the parameter, for messages
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
                           const std::string& name = "out");

/// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGPIPE that remove every temporary of
/// every live AtomicFileSet, then end the process with the signal's default action (so the
/// exit status still says which signal). For programs (the CLI); idempotent.
void remove_temporaries_on_signals();

}  // namespace selfalign
