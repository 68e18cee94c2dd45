// Outputs are written whole or not at all: an output appears under its name only when every byte
// of it was written, a failed or abandoned one leaves the file that was there before, and a link
// planted under an output's name is replaced, never written through.
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "core/output_file.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::test_output_file {

namespace fs = std::filesystem;

std::string text_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Names in `dir` (a leftover temporary would show here).
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> n;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) n.push_back(e.path().filename().string());
  std::sort(n.begin(), n.end());
  return n;
}

TEST(OutputFile, AppearsOnlyWhenCommittedAndLeavesNoTemporary) {
  const fs::path dir = test::fresh_test_dir(), p = dir / "out.csv";
  {
    OutputFile f(p);
    f << "a,b\n1,2\n";
    EXPECT_FALSE(fs::exists(p));  // still under its temporary name
    f.commit();
  }
  EXPECT_EQ(text_of(p), "a,b\n1,2\n");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"out.csv"});
}

TEST(OutputFile, AnUncommittedFileLeavesThePreviousOneAsItWas) {
  const fs::path dir = test::fresh_test_dir(), p = dir / "summary.json";
  write_output_file(p, "{\"old\": 1}\n");
  {
    OutputFile f(p, Durability::Record);
    f << "{\"new\": ";  // the command ends (an exception) before the record is whole
  }
  EXPECT_EQ(text_of(p), "{\"old\": 1}\n");
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"summary.json"});
}

TEST(OutputFile, ALinkUnderItsNameIsReplacedAndItsTargetUntouched) {
  const fs::path dir = test::fresh_test_dir();
  fs::create_directories(dir / "elsewhere");
  write_output_file(dir / "elsewhere/precious.txt", "mine\n");
  fs::create_symlink(dir / "elsewhere/precious.txt", dir / "state.csv");
  write_output_file(dir / "state.csv", "time_s\n");
  EXPECT_EQ(text_of(dir / "elsewhere/precious.txt"), "mine\n");
  EXPECT_FALSE(fs::is_symlink(fs::symlink_status(dir / "state.csv")));
  EXPECT_EQ(text_of(dir / "state.csv"), "time_s\n");
}

TEST(OutputFile, AMissingFolderIsAnOutputErrorNamingTheFile) {
  const fs::path p = test::fresh_test_dir() / "no_such_folder" / "x.csv";
  try {
    OutputFile f(p);
    FAIL() << "created " << p;
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(p.string() + ": cannot create: No such file or directory"), std::string::npos) << e.what();
  }
}

// A 64 KiB file system, where one can be mounted (root in a container; skipped elsewhere).
class FullDisk : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::fresh_test_dir();
    if (::mount("tmpfs", dir_.c_str(), "tmpfs", 0, "size=64k") != 0) GTEST_SKIP() << "cannot mount a tmpfs here";
    mounted_ = true;
  }
  void TearDown() override {
    if (mounted_) ::umount(dir_.c_str());
  }
  fs::path dir_;
  bool mounted_ = false;
};

TEST_F(FullDisk, AWriteBeyondTheDiskIsAnOutputErrorWithTheSystemsReason) {
  write_output_file(dir_ / "record.json", "{\"kept\": true}\n");
  OutputFile f(dir_ / "record.json", Durability::Record);
  const std::string row(1000, 'x');
  for (int i = 0; i < 200 && !f.failed(); ++i) f << row << '\n';  // 200 kB into 64 kB
  EXPECT_TRUE(f.failed());
  try {
    f.commit();
    FAIL() << "a truncated file was committed";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("record.json: cannot write: No space left on device"), std::string::npos) << e.what();
  }
  EXPECT_EQ(text_of(dir_ / "record.json"), "{\"kept\": true}\n");
}

}  // namespace gearsim::test_output_file
