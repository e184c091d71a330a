#include "selfalign/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
  throw InvalidParameter("output file", path, what + ": " + std::strerror(error));
}

// Creates "<path>.tmp-XXXXXX" exclusively, mode 0666 & ~umask (like an ordinary new file;
// mkstemp would give 0600). Returns the descriptor and sets `name`.
int create_temporary(const std::string& path, std::string& name) {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device entropy;
  std::mt19937_64 random(entropy());
  std::uniform_int_distribution<std::size_t> pick(0, sizeof kAlphabet - 2);
  for (int attempt = 0; attempt < 100; ++attempt) {
    name = path + ".tmp-";
    for (int i = 0; i < 6; ++i) name += kAlphabet[pick(random)];
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) fail(path, "cannot create a temporary file beside it", errno);
  }
  fail(path, "cannot create a temporary file beside it", EEXIST);
}

void write_all(int fd, std::string_view content, const std::string& path,
               const std::string& temporary) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      std::remove(temporary.c_str());
      fail(path, "cannot write", error);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL) {  // EINVAL: the file system cannot sync (fine)
    const int error = errno;
    ::close(fd);
    std::remove(temporary.c_str());
    fail(path, "cannot flush", error);
  }
  if (::close(fd) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    fail(path, "cannot close", error);
  }
}

}  // namespace

AtomicFileSet::~AtomicFileSet() {
  for (const Pending& p : pending_) std::remove(p.temporary.c_str());
}

void AtomicFileSet::add(const std::string& path, std::string_view content) {
  for (const Pending& p : pending_)
    if (p.target == path)
      throw InvalidParameter("output file", path, "must not be written twice in one run");
  std::string temporary;
  const int fd = create_temporary(path, temporary);
  write_all(fd, content, path, temporary);
  pending_.push_back({path, std::move(temporary)});
}

void AtomicFileSet::commit() {
  while (!pending_.empty()) {
    const Pending& p = pending_.front();
    if (std::rename(p.temporary.c_str(), p.target.c_str()) != 0) {
      const int error = errno;
      fail(p.target, "cannot rename the temporary " + p.temporary + " onto it", error);
    }
    pending_.erase(pending_.begin());
  }
}

void write_file_atomically(const std::string& path, std::string_view content) {
  AtomicFileSet files;
  files.add(path, content);
  files.commit();
}

}  // namespace selfalign
