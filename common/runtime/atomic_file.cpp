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

std::string Failure(const std::string& path, const std::string& what) {
  return "cannot write " + Quoted(path) + ": " + what + ": " + std::strerror(errno);
}

// A temporary name beside `path` no one can guess in advance.
std::string TemporaryName(const std::string& path) {
  static thread_local std::mt19937_64 random{std::random_device{}()};
  return path + ".tmp." + std::to_string(getpid()) + "." + std::to_string(random() % 1000000000);
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string tmp = TemporaryName(path);
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
  if (error.empty() && rename(tmp.c_str(), path.c_str()) != 0) error = Failure(path, "renaming " + tmp);
  if (!error.empty()) {
    unlink(tmp.c_str());
    throw std::runtime_error(error);
  }
}

bool PathExists(const std::string& path) {
  struct stat info;
  return lstat(path.c_str(), &info) == 0;
}

}  // namespace ws
