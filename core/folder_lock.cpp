#include "core/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "core/errors.hpp"

namespace gearsim {
namespace {

// What the holder wrote into the lock file (one line, at most 200 bytes, printable only).
std::string holder_of(int fd) {
  char buf[201] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string s;
  for (ssize_t i = 0; i < n && buf[i] != '\n'; ++i) s += (buf[i] >= 0x20 && buf[i] < 0x7f) ? buf[i] : '?';
  return s.empty() ? "another process" : s;
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& dir, const std::string& command) {
  const std::filesystem::path file = dir / kFileName;
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0644);
  if (fd_ < 0)
    throw InputError(file.string() + ": cannot make the folder's lock file: " + std::strerror(errno) +
                     (errno == ELOOP ? " (a link under its name)" : ""));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    throw InputError(file.string() + ": the folder's lock file is not a regular file");
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    const std::string holder = err == EWOULDBLOCK ? holder_of(fd_) : "";
    ::close(fd_);
    if (err != EWOULDBLOCK) throw InputError(file.string() + ": cannot lock the folder: " + std::strerror(err));
    throw FolderBusy(dir.string() + ": in use by " + holder +
                     ": one command writes into a folder at a time (wait for it, or choose another folder)");
  }
  const std::string me = command + " (pid " + std::to_string(::getpid()) + ", since " + now_utc() + ")\n";
  // The holder's line is information for a refused second writer; a failure to write it leaves
  // the lock held and only the refusal's message poorer.
  [[maybe_unused]] const bool described =
      ::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, me.data(), me.size(), 0) == static_cast<ssize_t>(me.size());
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the flock
}

}  // namespace gearsim
