// An output file written whole or not at all. The text goes to a temporary file beside the
// target (".NAME.partial-PID", in the same folder, so the rename cannot cross a file system);
// commit() checks every write, flushes, fsyncs a record, closes and renames it into place. A
// failed write (a full disk, a lost permission) is an OutputError naming the file and the
// system's reason; the file that was there before stays as it was, and the temporary is removed.
// Never through a link: the temporary is created with O_EXCL | O_NOFOLLOW, and rename() replaces
// a link planted under the target's name instead of writing through it — outputs go only inside
// the chosen folder. Not a reader (core/input_file.hpp) and not a folder's lock (core/folder_lock.hpp).
#pragma once

#include <filesystem>
#include <initializer_list>
#include <memory>
#include <ostream>
#include <string>
#include <system_error>

namespace gearsim {

// How much a committed output is worth keeping through a power cut.
enum class Durability {
  Plain,  // renamed into place; the system writes it back when it will (plots, tables)
  Record,  // fsynced (the file, then its folder) before commit() returns: run records, logs
};

// A path a library writes itself (HDF5, libpng): written under temp(), moved to target() by
// commit(). The temporary is removed when the object goes without a commit.
class StagedPath {
 public:
  explicit StagedPath(std::filesystem::path target, Durability durability = Durability::Plain);
  ~StagedPath();
  StagedPath(const StagedPath&) = delete;
  StagedPath& operator=(const StagedPath&) = delete;

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temp() const { return temp_; }
  // fsyncs (a Record) and renames temp() to target(); OutputError naming target() otherwise.
  void commit();
  bool committed() const { return committed_; }

 private:
  std::filesystem::path target_, temp_;
  Durability durability_;
  bool committed_ = false;
};

// A text or binary output as a std::ostream. Writes go through a buffer straight to the file
// descriptor; the first failed write keeps its errno and fails every later one (the stream's
// badbit is set, so `if (!out)` tells at once).
class OutputFile : public std::ostream {
 public:
  // Creates the temporary; OutputError naming `target` when it cannot be created.
  explicit OutputFile(std::filesystem::path target, Durability durability = Durability::Plain);
  ~OutputFile() override;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  const std::filesystem::path& target() const { return staged_.target(); }
  // True once a write has failed; the reason is failure().
  bool failed() const;
  std::string failure() const;
  // Flushes, checks, closes and renames into place; OutputError naming target() and the reason
  // when any write failed or the close or rename does. After a throw nothing was put in place.
  void commit();
  // Closes and removes the temporary without putting anything in place (an output abandoned).
  void discard();

 private:
  class Buffer;
  std::unique_ptr<Buffer> buffer_;
  StagedPath staged_;
};

// Commits each file (null pointers skipped), all of them even when one fails; OutputError naming
// every one that could not be written.
void commit_all(std::initializer_list<OutputFile*> files);

// Writes `target` as one OutputFile filled by fill(std::ostream&), and commits it; a `return`
// inside `fill` ends the file there.
template <class Fill>
void write_output(const std::filesystem::path& target, Fill&& fill, Durability durability = Durability::Plain) {
  OutputFile out(target, durability);
  fill(static_cast<std::ostream&>(out));
  out.commit();
}

// Writes `text` to `target` as one OutputFile and commits it.
void write_output_file(const std::filesystem::path& target, const std::string& text, Durability durability = Durability::Plain);

// Points the file descriptor `fd` at /dev/null, so that a library holding a file whose writes
// failed (HDF5 flushes its metadata when it closes, and crashes at exit when that fails) can
// close it without writing; the file itself is then removed by its StagedPath.
void divert_to_null(int fd);

// Removes a symbolic link at p (the link, not what it points to); anything else stays.
void unlink_output(const std::filesystem::path& p);

// The output folder p, created where missing, never through a link under its name.
void make_output_dir(const std::filesystem::path& p, std::error_code& ec);

}  // namespace gearsim
