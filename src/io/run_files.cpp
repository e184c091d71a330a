#include "selfalign/io/run_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <mutex>
#include <vector>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {

namespace fs = std::filesystem;

// What a path names: an existing file (its device and inode), or a file to be created (its
// folder's device and inode, and its name), or, where even the folder does not exist, the
// lexically normal absolute path.
struct FileIdentity {
  enum class Kind { existing, new_in_folder, unresolved } kind = Kind::unresolved;
  dev_t device = 0;
  ino_t inode = 0;
  std::string name;      // new_in_folder: the file's name in its folder
  std::string absolute;  // unresolved
};

FileIdentity identify(const std::string& path) {
  const std::string target = final_target(path);
  FileIdentity id;
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) {
    id.kind = FileIdentity::Kind::existing;
    id.device = st.st_dev;
    id.inode = st.st_ino;
    return id;
  }
  const fs::path p(target);
  const std::string folder = p.has_parent_path() ? p.parent_path().string() : ".";
  if (::stat(folder.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    id.kind = FileIdentity::Kind::new_in_folder;
    id.device = st.st_dev;
    id.inode = st.st_ino;
    id.name = p.filename().string();
    return id;
  }
  std::error_code ec;
  id.absolute = fs::absolute(target, ec).lexically_normal().string();
  if (ec) id.absolute = p.lexically_normal().string();
  return id;
}

bool same_identity(const FileIdentity& a, const FileIdentity& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == FileIdentity::Kind::unresolved) return a.absolute == b.absolute;
  return a.device == b.device && a.inode == b.inode && a.name == b.name;
}

// A registered file: identified again at each comparison, so that an entry names the file its
// path names now (an output replaced by a rename, or a file deleted since: a test's temporary
// folder, whose inode a new file may reuse, is then no longer that file).
struct Registered {
  std::string path;      // as given, for messages
  std::string absolute;  // the path from the current folder at registration
  std::string label;     // inputs: the flag ("--config"); outputs: the name ("out")
  FileIdentity id() const { return identify(absolute); }
};

Registered registered(const std::string& path, const std::string& label) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return {path, ec ? path : absolute.string(), label};
}

struct RunFiles {
  std::mutex mutex;
  std::vector<Registered> inputs, outputs;
};

RunFiles& run_files() {
  static RunFiles files;
  return files;
}

[[noreturn]] void refuse_input_as_output(const std::string& name, const std::string& path,
                                         const std::string& flag) {
  throw InvalidParameter(name, path,
                         "is the input file given as " + flag + "; choose another path");
}

}  // namespace

std::string final_target(const std::string& path) {
  std::string current = path;
  for (int hop = 0; hop < 40; ++hop) {
    struct stat st {};
    if (::lstat(current.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return current;
    std::array<char, 4096> buffer{};
    const ssize_t n = ::readlink(current.c_str(), buffer.data(), buffer.size() - 1);
    if (n <= 0) return current;
    const fs::path target(std::string(buffer.data(), static_cast<std::size_t>(n)));
    current = target.is_absolute() ? target.string()
                                   : (fs::path(current).parent_path() / target).string();
  }
  return current;
}

bool same_file(const std::string& a, const std::string& b) {
  return same_identity(identify(a), identify(b));
}

void register_input_file(const std::string& path, const std::string& flag) {
  Registered in = registered(path, flag);
  const FileIdentity id = in.id();
  RunFiles& files = run_files();
  std::lock_guard lock(files.mutex);
  for (const Registered& out : files.outputs)
    if (same_identity(out.id(), id)) refuse_input_as_output(out.label, out.path, flag);
  for (const Registered& known : files.inputs)
    if (known.label == flag && same_identity(known.id(), id)) return;
  files.inputs.push_back(std::move(in));
}

void require_input_file(const std::string& name, const std::string& path,
                        const std::string& flag, std::uintmax_t max_bytes) {
  if (path.empty()) throw InvalidParameter(name, "\"\"", "must name a file");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InvalidParameter(name, path, "is a directory; give a file");
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
    throw InvalidParameter(name, path,
                           "must be a regular file (a FIFO or device would block or never end)");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > max_bytes)
    throw InvalidParameter(name, path,
                           "is larger than " + std::to_string(max_bytes >> 20) + " MB");
  register_input_file(path, flag);  // no output may replace it
}

std::optional<std::string> input_file_flag(const std::string& path) {
  const FileIdentity id = identify(path);
  RunFiles& files = run_files();
  std::lock_guard lock(files.mutex);
  for (const Registered& in : files.inputs)
    if (same_identity(id, in.id())) return in.label;
  return std::nullopt;
}

void require_output_path(const std::string& name, const std::string& path) {
  if (path.empty()) throw InvalidParameter(name, "\"\"", "must be a file path");
  if (path == "-") return;  // standard output
  struct stat st {};
  if (::stat(final_target(path).c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InvalidParameter(name, path, "is a directory; give a file path");
  Registered out = registered(path, name);
  const FileIdentity id = out.id();
  RunFiles& files = run_files();
  std::lock_guard lock(files.mutex);
  for (const Registered& in : files.inputs)
    if (same_identity(in.id(), id)) refuse_input_as_output(name, path, in.label);
  for (const Registered& other : files.outputs)
    if (other.label != name && same_identity(other.id(), id))
      throw InvalidParameter(name, path,
                             "is the same file as --" + other.label + " (" + other.path +
                                 "); give each output its own file");
  std::erase_if(files.outputs, [&name](const Registered& r) { return r.label == name; });
  files.outputs.push_back(std::move(out));
}

void forget_run_files() {
  RunFiles& files = run_files();
  std::lock_guard lock(files.mutex);
  files.inputs.clear();
  files.outputs.clear();
}

}  // namespace selfalign
