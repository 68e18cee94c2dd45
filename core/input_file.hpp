// Input files read through one bounded reader: regular files only (a FIFO, a device such as
// /dev/zero, a folder or a link loop is refused at once, checked with fstat on the opened file,
// never blocking on a FIFO's open), and at most a stated number of bytes, counted while reading.
// Errors are InputError naming the file and what was expected. Not a parser: the YAML, JSON and
// CSV readers take the text or the stream from here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <istream>
#include <memory>
#include <string>

namespace gearsim {

// The whole of `path` as bytes; InputError naming it (and `what` it was to be, e.g. "a scenario
// file") when it is not a regular file, cannot be read, or holds more than max_bytes.
std::string read_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what);

// The checks of read_input_file() without the reading, for a file a library opens itself (HDF5):
// its size; InputError as read_input_file() gives it. (The file may change between this check
// and the library's open; the check keeps a FIFO or a device from blocking or flooding it.)
std::size_t check_input_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what);

// A regular file opened for reading as a stream (for readers that go line by line through files
// too large to hold whole, e.g. a run's logs). The size is fixed when opened: a file larger than
// max_bytes is refused then.
class InputFile : public std::istream {
 public:
  InputFile(const std::filesystem::path& path, std::size_t max_bytes, const std::string& what);
  ~InputFile() override;
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  std::size_t size() const { return size_; }

 private:
  class Buffer;
  std::unique_ptr<Buffer> buffer_;
  std::size_t size_ = 0;
};

}  // namespace gearsim
