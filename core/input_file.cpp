#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <streambuf>
#include <vector>

#include "core/errors.hpp"

namespace gearsim {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// The opened descriptor of a regular file of at most max_bytes, and its size.
int open_regular(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what, std::size_t& size) {
  // O_NONBLOCK: opening a FIFO for reading does not wait for a writer; cleared again below.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(path.string() + ": cannot open " + what + ": " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    throw InputError(path.string() + ": cannot examine " + what + ": " + std::strerror(err));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    throw InputError(path.string() + ": expected " + what + " (a regular file), got " + kind_of(st.st_mode));
  }
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    ::close(fd);
    throw InputError(path.string() + ": " + std::to_string(st.st_size) + " bytes: larger than the " + std::to_string(max_bytes) +
                     " bytes " + what + " may have");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  size = static_cast<std::size_t>(st.st_size);
  return fd;
}

}  // namespace

std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what) {
  std::size_t size = 0;
  const int fd = open_regular(path, max_bytes, what, size);
  std::string text;
  text.reserve(size);
  std::vector<char> chunk(1 << 16);
  while (true) {
    const ssize_t n = ::read(fd, chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      throw InputError(path.string() + ": cannot read " + what + ": " + std::strerror(err));
    }
    if (n == 0) break;
    text.append(chunk.data(), static_cast<std::size_t>(n));
    // The file may grow while it is read: the bound holds for what is read, not only the size.
    if (text.size() > max_bytes) {
      ::close(fd);
      throw InputError(path.string() + ": grew past the " + std::to_string(max_bytes) + " bytes " + what + " may have while it was read");
    }
  }
  ::close(fd);
  return text;
}

std::size_t check_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what) {
  std::size_t size = 0;
  ::close(open_regular(path, max_bytes, what, size));
  return size;
}

// A read buffer over a descriptor that stops after the size the file had when opened.
class InputFile::Buffer : public std::streambuf {
 public:
  Buffer(int fd, std::size_t limit) : fd_(fd), left_(limit), data_(1 << 16) {}
  ~Buffer() override { ::close(fd_); }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (left_ == 0) return traits_type::eof();
    ssize_t n;
    do n = ::read(fd_, data_.data(), std::min(data_.size(), left_));
    while (n < 0 && errno == EINTR);
    if (n <= 0) return traits_type::eof();
    left_ -= static_cast<std::size_t>(n);
    setg(data_.data(), data_.data(), data_.data() + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  int fd_;
  std::size_t left_;
  std::vector<char> data_;
};

InputFile::InputFile(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what) : std::istream(nullptr) {
  const int fd = open_regular(path, max_bytes, what, size_);
  buffer_ = std::make_unique<Buffer>(fd, size_);
  rdbuf(buffer_.get());
}

InputFile::~InputFile() { rdbuf(nullptr); }

}  // namespace gearsim
