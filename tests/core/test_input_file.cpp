// Inputs are read through one bounded reader: regular files only, refused at once otherwise (a
// FIFO without a writer does not block), and never more than the stated bytes.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "core/input_file.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::test_input_file {

namespace fs = std::filesystem;

std::string refusal(const fs::path& p, std::size_t max_bytes) {
  try {
    read_input_file(p, max_bytes, "a scenario file");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(InputFile, ReadsARegularFileWhole) {
  const fs::path p = test::fresh_test_dir() / "s.yaml";
  std::ofstream(p) << "duration_s: 1\n";
  EXPECT_EQ(read_input_file(p, 100, "a scenario file"), "duration_s: 1\n");
}

TEST(InputFile, AFifoIsRefusedAtOnceNotWaitedOn) {
  const fs::path p = test::fresh_test_dir() / "pipe.yaml";
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const std::string e = refusal(p, 100);
  // Refused, not blocked until a writer comes: well under a second.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
  EXPECT_NE(e.find("pipe.yaml: expected a scenario file (a regular file), got a FIFO"), std::string::npos) << e;
}

TEST(InputFile, ADeviceAndAFolderAreRefusedByKind) {
  EXPECT_NE(refusal("/dev/zero", 100).find("/dev/zero: expected a scenario file (a regular file), got a device"), std::string::npos);
  const fs::path d = test::fresh_test_dir();
  EXPECT_NE(refusal(d, 100).find("got a folder"), std::string::npos) << refusal(d, 100);
}

TEST(InputFile, ALinkToADeviceIsRefusedAsTheDevice) {
  const fs::path p = test::fresh_test_dir() / "state.csv";
  fs::create_symlink("/dev/zero", p);
  EXPECT_NE(refusal(p, 100).find("got a device"), std::string::npos) << refusal(p, 100);
}

TEST(InputFile, AFileLargerThanTheBoundIsRefusedWithBothSizes) {
  const fs::path p = test::fresh_test_dir() / "big.yaml";
  std::ofstream(p) << std::string(101, 'x');
  EXPECT_NE(refusal(p, 100).find("big.yaml: 101 bytes: larger than the 100 bytes a scenario file may have"), std::string::npos)
      << refusal(p, 100);
  EXPECT_EQ(refusal(p, 101), "");
}

TEST(InputFile, TheStreamReadsTheFileLineByLine) {
  const fs::path p = test::fresh_test_dir() / "state.csv";
  std::ofstream(p) << "time_s\n0.1\n0.2\n";
  InputFile in(p, 1000, "a run's CSV log");
  std::string line, all;
  while (std::getline(in, line)) all += line + ";";
  EXPECT_EQ(all, "time_s;0.1;0.2;");
  EXPECT_EQ(in.size(), 15u);  // 7 + 4 + 4 bytes
}

}  // namespace gearsim::test_input_file
