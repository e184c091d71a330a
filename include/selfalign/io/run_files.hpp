#pragma once
/// \file run_files.hpp
/// The files of one run: every input it reads and every output it will write, in one registry,
/// so that an output never replaces an input and two outputs never name one file.
///
/// Files are compared by identity, not by spelling: an existing file by its device and inode
/// (symbolic links followed, so `link`, `./x`, `sub/../x` and a hard link all name `x`); a file
/// not created yet by the identity of its folder and its name (`./new.csv` and `new.csv` are
/// one file). A registered path is identified again at each comparison: it stands for the file
/// it names now (one deleted since is no longer that file, whatever inode a new file reuses).
/// A run registers its inputs and outputs before its work (the CLI does it for every
/// FILE option as it parses, apps/selfalign/main.cpp, and for the files a config names,
/// register_config_files), and the readers and AtomicFileSet (atomic_file.hpp) register what
/// they read and write again, so a registration missed by a front end is still caught before a
/// file is replaced. Thread-safe. "-" (standard output) is not a file and is never registered.

#include <cstdint>
#include <optional>
#include <string>

namespace selfalign {

/// The file `path` finally names: symbolic links followed, also a dangling one (whose target
/// a write would create); at most 40 hops, as the kernel allows.
std::string final_target(const std::string& path);

/// Whether `a` and `b` name the same file (by identity, see above). Two paths of which only one
/// exists are different files.
bool same_file(const std::string& a, const std::string& b);

/// Records that this run reads `path` as the input given as `flag` (e.g. "--config"). Throws
/// InvalidParameter(<output's name>, <output's path>, "is the input file given as <flag>; ...")
/// when an output registered so far is that file.
void register_input_file(const std::string& path, const std::string& flag);

/// Checks that `path` can be read as the input `name`: a non-empty path that, where it exists,
/// is a regular file (a folder is refused, and a FIFO or device, whose read would block or
/// never end) of at most `max_bytes` bytes; then registers it under `flag`
/// (register_input_file). Throws InvalidParameter(name, path, ...). A missing file is left to
/// the reader, which names it.
void require_input_file(const std::string& name, const std::string& path,
                        const std::string& flag, std::uintmax_t max_bytes);

/// The flag of the registered input that `path` names, or none.
std::optional<std::string> input_file_flag(const std::string& path);

/// Checks that `path` can be the output `name` (the parameter without dashes: "out",
/// "summary", "runs-csv") and registers it: throws InvalidParameter(name, path, ...) when it is
/// empty, a directory, a registered input, or the file of another registered output. An output
/// registered again under its name replaces the earlier path (a config's `out` overridden by
/// --out). "-" is accepted and not registered.
void require_output_path(const std::string& name, const std::string& path);

/// Forgets every registered input and output (a new run in the same process; tests).
void forget_run_files();

}  // namespace selfalign
