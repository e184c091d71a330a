#include "selfalign/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <mutex>
#include <random>

#include "selfalign/error.hpp"
#include "selfalign/io/run_files.hpp"

namespace selfalign {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& path, const std::string& what,
                       int error) {
  throw InvalidParameter(name, path, what + ": " + std::strerror(error));
}

// ---- temporaries, for removal on a signal ------------------------------------------------

constexpr std::size_t kSlots = 64;         // live temporaries at once (a run writes a few)
constexpr std::size_t kPathCapacity = 4096;
std::array<std::atomic<bool>, kSlots> g_slot_used{};
std::array<std::array<char, kPathCapacity>, kSlots> g_slot_path{};

void track(const std::string& temporary) {
  if (temporary.size() >= kPathCapacity) return;  // not removable on a signal; still on error
  for (std::size_t i = 0; i < kSlots; ++i) {
    if (g_slot_used[i].load()) continue;
    std::memcpy(g_slot_path[i].data(), temporary.c_str(), temporary.size() + 1);
    bool expected = false;
    if (g_slot_used[i].compare_exchange_strong(expected, true)) return;
  }
}

void untrack(const std::string& temporary) {
  for (std::size_t i = 0; i < kSlots; ++i)
    if (g_slot_used[i].load() && temporary == g_slot_path[i].data()) g_slot_used[i].store(false);
}

extern "C" void remove_temporaries_and_reraise(int signal) {
  for (std::size_t i = 0; i < kSlots; ++i)
    if (g_slot_used[i].load()) ::unlink(g_slot_path[i].data());  // async-signal-safe
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// ---- writing ---------------------------------------------------------------------------------

// Creates "<path>.tmp-XXXXXX" exclusively, mode 0666 & ~umask (like an ordinary new file;
// mkstemp would give 0600). Returns the descriptor and sets `temporary`.
int create_temporary(const std::string& name, const std::string& path, std::string& temporary) {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device entropy;
  std::mt19937_64 random(entropy());
  std::uniform_int_distribution<std::size_t> pick(0, sizeof kAlphabet - 2);
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary = path + ".tmp-";
    for (int i = 0; i < 6; ++i) temporary += kAlphabet[pick(random)];
    track(temporary);  // before it exists: a signal in between unlinks nothing
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    const int error = errno;
    untrack(temporary);
    if (error != EEXIST) fail(name, path, "cannot create a temporary file beside it", error);
  }
  fail(name, path, "cannot create a temporary file beside it", EEXIST);
}

// Writes all of content to fd; returns 0 or the errno of the failure. Closes fd.
int write_and_close(int fd, std::string_view content, bool sync) {
  const char* data = content.data();
  std::size_t left = content.size();
  int error = 0;
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : EIO;
      break;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (!error && sync && ::fsync(fd) != 0 && errno != EINVAL) error = errno;  // EINVAL: cannot
  if (::close(fd) != 0 && !error) error = errno;
  return error;
}

void remove_temporary(const std::string& temporary) {
  std::remove(temporary.c_str());
  untrack(temporary);
}

bool is_stream(const struct stat& st) {
  return S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ||
         S_ISSOCK(st.st_mode);
}

}  // namespace

AtomicFileSet::~AtomicFileSet() {
  for (const Pending& p : pending_)
    if (!p.temporary.empty()) remove_temporary(p.temporary);
}

void AtomicFileSet::add(const std::string& path, std::string_view content,
                        const std::string& name) {
  require_output_path(name, path);  // registers it: not an input, not another output's file
  Pending p;
  p.name = name;
  p.path = path;
  if (path == "-") {
    p.to_stdout = true;
    p.target = path;
  } else {
    p.target = final_target(path);
  }
  for (const Pending& q : pending_)
    if ((q.to_stdout && p.to_stdout) ||
        (!q.to_stdout && !p.to_stdout && same_file(q.path, p.path)))
      throw InvalidParameter(name, path, "must not be written twice in one run");
  struct stat st {};
  p.existed = !p.to_stdout && ::stat(p.target.c_str(), &st) == 0;
  if (p.to_stdout || (p.existed && is_stream(st))) {
    p.stream = !p.to_stdout;
    p.content = std::string(content);  // written at commit: never replace a FIFO or device
    pending_.push_back(std::move(p));
    return;
  }
  const int fd = create_temporary(name, p.target, p.temporary);
  if (p.existed) ::fchmod(fd, st.st_mode & 07777);  // a replaced file keeps its mode
  if (const int error = write_and_close(fd, content, true)) {
    remove_temporary(p.temporary);
    fail(name, path, "cannot write", error);
  }
  pending_.push_back(std::move(p));
}

void AtomicFileSet::commit() {
  // FIFOs and devices are opened first, so that one that cannot be written (a FIFO nobody
  // reads: ENXIO rather than blocking for ever) stops the commit before any file is replaced.
  std::vector<int> streams(pending_.size(), -1);
  auto close_streams = [&streams] {
    for (int fd : streams)
      if (fd >= 0) ::close(fd);
  };
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    if (!pending_[i].stream) continue;
    const int fd = ::open(pending_[i].target.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      const int error = errno;
      close_streams();
      fail(pending_[i].name, pending_[i].target,
           error == ENXIO ? "is a FIFO with no reader" : "cannot open it for writing", error);
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // then write blocking
    streams[i] = fd;
  }
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    Pending& p = pending_[i];
    if (p.temporary.empty()) continue;
    if (std::rename(p.temporary.c_str(), p.target.c_str()) != 0) {
      const int error = errno;
      for (std::size_t j = 0; j < pending_.size(); ++j) {
        Pending& q = pending_[j];
        if (j < i && !q.stream && !q.to_stdout && !q.existed)
          std::remove(q.target.c_str());  // undo what this set created
        if (!q.temporary.empty()) remove_temporary(q.temporary);
        q.temporary.clear();
      }
      const std::string name = p.name, target = p.target;
      close_streams();
      pending_.clear();
      fail(name, target, "cannot replace it", error);
    }
    untrack(p.temporary);
    p.temporary.clear();
  }
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    if (streams[i] < 0) continue;
    const int error = write_and_close(streams[i], pending_[i].content, false);
    streams[i] = -1;
    if (error) {
      close_streams();
      fail(pending_[i].name, pending_[i].target, "cannot write", error);
    }
  }
  for (const Pending& p : pending_)
    if (p.to_stdout) std::cout << p.content << std::flush;
  pending_.clear();
}

void write_file_atomically(const std::string& path, std::string_view content,
                           const std::string& name) {
  AtomicFileSet files;
  files.add(path, content, name);
  files.commit();
}

void remove_temporaries_on_signals() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal, &action, nullptr);
    }
  });
}

}  // namespace selfalign
