#include "runtime/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>

#include "runtime/escaped.h"

namespace ws {
namespace {

thread_local OutputSet* collecting = nullptr;  // the set WriteFileAtomically writes into

std::string Failure(const std::string& path, const std::string& what) {
  return "cannot write " + Quoted(path) + ": " + what + ": " + std::strerror(errno);
}

// A temporary name beside `path` no one can guess in advance.
std::string TemporaryName(const std::string& path) {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  return path + ".tmp." + std::to_string(getpid()) + "." + std::to_string(random() % 1000000000);
}

// `bytes` in a new file `tmp`, written, synced and closed, every step
// checked; removed on failure (std::runtime_error naming `path`).
void WriteNew(const std::string& path, const std::string& tmp, const std::string& bytes) {
  const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(Failure(path, "creating " + tmp));
  std::string error;
  for (size_t done = 0; done < bytes.size() && error.empty();) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) error = Failure(path, "writing");
    else done += size_t(n);
  }
  if (error.empty() && fsync(fd) != 0) error = Failure(path, "fsync");
  if (close(fd) != 0 && error.empty()) error = Failure(path, "closing");
  if (!error.empty()) {
    unlink(tmp.c_str());
    throw std::runtime_error(error);
  }
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& bytes) {
  if (collecting) return collecting->Add(path, bytes);
  OutputSet one;
  one.Add(path, bytes);
  one.Commit();
}

bool PathExists(const std::string& path) {
  struct stat info;
  return lstat(path.c_str(), &info) == 0;
}

OutputSet::OutputSet() : outer_(collecting) { collecting = this; }

OutputSet::~OutputSet() {
  for (const Pending& p : pending_) unlink(p.tmp.c_str());
  if (collecting == this) collecting = outer_;
}

void OutputSet::Add(const std::string& path, const std::string& bytes) {
  const std::string tmp = TemporaryName(path);
  WriteNew(path, tmp, bytes);
  pending_.push_back({path, tmp});
}

void OutputSet::Commit() {
  if (collecting == this) collecting = outer_;
  for (size_t i = 0; i < pending_.size(); ++i)
    if (rename(pending_[i].tmp.c_str(), pending_[i].path.c_str()) != 0) {
      const std::string error = Failure(pending_[i].path, "renaming " + pending_[i].tmp);
      pending_.erase(pending_.begin(), pending_.begin() + long(i));  // those are in place
      throw std::runtime_error(error);
    }
  pending_.clear();
}

}  // namespace ws
