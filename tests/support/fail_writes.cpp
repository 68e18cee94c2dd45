// Test support: a writer that fails. Preloaded (LD_PRELOAD) into a gearsim process, it makes the
// Nth write to a regular file, and every later one, fail with ENOSPC, as a full disk does; N is
// GEARSIM_FAIL_WRITES_FROM (unset or 0: no write fails). Writes to pipes and terminals (the
// messages a test reads) pass. write, pwrite and writev are what gearsim, HDF5, libpng and
// FFmpeg write files with.
#include <dlfcn.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>

namespace {

std::atomic<long> g_writes{0};

// True when this write to fd is to fail.
bool fails(int fd) {
  static const long from = [] {
    const char* v = std::getenv("GEARSIM_FAIL_WRITES_FROM");
    return v ? std::atol(v) : 0L;
  }();
  struct stat st {};
  if (from <= 0 || ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return false;
  return ++g_writes >= from;
}

template <class F>
F real(const char* name) {
  return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

}  // namespace

extern "C" {

ssize_t write(int fd, const void* buf, size_t n) {
  static const auto next = real<ssize_t (*)(int, const void*, size_t)>("write");
  if (fails(fd)) return errno = ENOSPC, -1;
  return next(fd, buf, n);
}

ssize_t pwrite(int fd, const void* buf, size_t n, off_t offset) {
  static const auto next = real<ssize_t (*)(int, const void*, size_t, off_t)>("pwrite");
  if (fails(fd)) return errno = ENOSPC, -1;
  return next(fd, buf, n, offset);
}

ssize_t pwrite64(int fd, const void* buf, size_t n, off64_t offset) {
  static const auto next = real<ssize_t (*)(int, const void*, size_t, off64_t)>("pwrite64");
  if (fails(fd)) return errno = ENOSPC, -1;
  return next(fd, buf, n, offset);
}

ssize_t writev(int fd, const struct iovec* iov, int count) {
  static const auto next = real<ssize_t (*)(int, const struct iovec*, int)>("writev");
  if (fails(fd)) return errno = ENOSPC, -1;
  return next(fd, iov, count);
}

}  // extern "C"
