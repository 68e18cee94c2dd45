#include "core/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <streambuf>
#include <vector>

#include "core/errors.hpp"

namespace gearsim {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void fail_output(const fs::path& target, const std::string& what, int err) {
  throw OutputError(target.string() + ": " + what + ": " + std::strerror(err));
}

// ".NAME.partial-PID-N" beside the target: unique within the process, and recognisable as a
// leftover of a killed command (core/folder_manifest.hpp removes those of its own outputs).
fs::path temp_beside(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  // Appended piece by piece: GCC 12's -Wrestrict misreads `"." + std::string&&` (a false positive).
  std::string name(".");
  name += target.filename().string();
  name += ".partial-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  return target.parent_path() / name;
}

// fsync of the folder that holds p, so that a rename into it survives a power cut.
int sync_folder(const fs::path& p) {
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int rc = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  // Some file systems (tmpfs) have nothing to sync for a folder and say EINVAL.
  return rc == EINVAL ? 0 : rc;
}

}  // namespace

StagedPath::StagedPath(fs::path target, Durability durability)
    : target_(std::move(target)), temp_(temp_beside(target_)), durability_(durability) {}

StagedPath::~StagedPath() {
  if (committed_) return;
  std::error_code ec;
  fs::remove(temp_, ec);
}

void StagedPath::commit() {
  GEARSIM_CHECK(!committed_, target_.string() + ": committed twice");
  if (durability_ == Durability::Record) {
    const int fd = ::open(temp_.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) fail_output(target_, "cannot open what was written to sync it", errno);
    const int rc = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    if (rc) fail_output(target_, "cannot sync to disk", rc);
  }
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) fail_output(target_, "cannot put in place", errno);
  committed_ = true;
  if (durability_ == Durability::Record)
    if (const int rc = sync_folder(target_)) fail_output(target_, "cannot sync its folder to disk", rc);
}

// A write buffer over a file descriptor that keeps the errno of the first failed write.
class OutputFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), data_(1 << 16) { setp(data_.data(), data_.data() + data_.size()); }
  ~Buffer() override { close(); }

  int error() const { return error_; }
  // Writes what is buffered; false (and error() set) when the system refused.
  bool drain() {
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0 && !error_) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0)
        error_ = errno;
      else if (n == 0)
        error_ = EIO;
      else
        p += n, left -= static_cast<std::size_t>(n);
    }
    setp(data_.data(), data_.data() + data_.size());
    return !error_;
  }
  // Closes the descriptor; false (and error() set) when the close reports a failed write.
  bool close() {
    if (fd_ < 0) return !error_;
    if (::close(fd_) != 0 && !error_) error_ = errno;
    fd_ = -1;
    return !error_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  int fd_;
  int error_ = 0;
  std::vector<char> data_;
};

OutputFile::OutputFile(fs::path target, Durability durability) : std::ostream(nullptr), staged_(std::move(target), durability) {
  ::unlink(staged_.temp().c_str());  // a leftover of a process that had this pid, never followed
  const int fd = ::open(staged_.temp().c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) fail_output(staged_.target(), "cannot create", errno);
  buffer_ = std::make_unique<Buffer>(fd);
  rdbuf(buffer_.get());
}

OutputFile::~OutputFile() {
  rdbuf(nullptr);
  buffer_.reset();  // closes; the StagedPath removes an uncommitted temporary
}

bool OutputFile::failed() const { return buffer_->error() != 0 || !good(); }

std::string OutputFile::failure() const {
  if (buffer_->error()) return std::strerror(buffer_->error());
  return good() ? "" : "the output stream failed";
}

void OutputFile::commit() {
  flush();
  buffer_->drain();
  buffer_->close();
  if (buffer_->error()) fail_output(target(), "cannot write", buffer_->error());
  if (!good()) throw OutputError(target().string() + ": cannot write: the output stream failed");
  staged_.commit();
}

void OutputFile::discard() {
  setstate(std::ios::badbit);
  buffer_->close();
}

void commit_all(std::initializer_list<OutputFile*> files) {
  std::string failures;
  for (OutputFile* f : files) {
    if (!f) continue;
    try {
      f->commit();
    } catch (const OutputError& e) {
      failures += (failures.empty() ? "" : "; ") + std::string(e.what());
    }
  }
  if (!failures.empty()) throw OutputError(failures);
}

void write_output_file(const fs::path& target, const std::string& text, Durability durability) {
  OutputFile out(target, durability);
  out << text;
  out.commit();
}

void divert_to_null(int fd) {
  const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null_fd < 0) return;
  ::dup3(null_fd, fd, O_CLOEXEC);
  ::close(null_fd);
}

void unlink_output(const fs::path& p) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(p, ec))) fs::remove(p, ec);
}

void make_output_dir(const fs::path& p, std::error_code& ec) {
  unlink_output(p);
  fs::create_directories(p, ec);
}

}  // namespace gearsim
