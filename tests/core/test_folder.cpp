// One writer per output folder (a lock that names its holder) and the manifest of what gearsim
// wrote there: a new run removes exactly the listed files, never a user's, never through a link,
// and a manifest that would reach outside the folder is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "core/folder_lock.hpp"
#include "core/folder_manifest.hpp"
#include "tests/support/asset_scenario.hpp"

namespace gearsim::test_folder {

namespace fs = std::filesystem;

void touch(const fs::path& p) { std::ofstream(p) << "x\n"; }

TEST(FolderLock, ASecondWriterIsRefusedNamingTheHolder) {
  const fs::path dir = test::fresh_test_dir();
  const FolderLock first(dir, "gearsim run");
  try {
    const FolderLock second(dir, "gearsim analyze");
    FAIL() << "two writers held " << dir;
  } catch (const FolderBusy& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(dir.string() + ": in use by gearsim run (pid " + std::to_string(::getpid())), std::string::npos) << m;
  }
}

TEST(FolderLock, IsFreeAgainOnceItsHolderIsGone) {
  const fs::path dir = test::fresh_test_dir();
  { const FolderLock first(dir, "gearsim run"); }
  EXPECT_NO_THROW(FolderLock(dir, "gearsim run"));
}

TEST(FolderManifest, ANewRunRemovesOnlyTheListedFiles) {
  const fs::path dir = test::fresh_test_dir();
  FolderManifest m = FolderManifest::read(dir);
  EXPECT_FALSE(m.exists());
  m.add_and_write(dir, {"state.csv", "frames/overview_00000.png"});
  fs::create_directories(dir / "frames");
  touch(dir / "state.csv");
  touch(dir / "frames/overview_00000.png");
  touch(dir / "frames/holiday.png");  // a user's, beside gearsim's
  touch(dir / "notes.txt");
  touch(dir / ".state.csv.partial-123-0");  // a killed run's temporary
  FolderManifest again = FolderManifest::read(dir);
  EXPECT_EQ(again.remove_listed(dir), 2);
  EXPECT_FALSE(fs::exists(dir / "state.csv"));
  EXPECT_FALSE(fs::exists(dir / "frames/overview_00000.png"));
  EXPECT_FALSE(fs::exists(dir / ".state.csv.partial-123-0"));
  EXPECT_TRUE(fs::exists(dir / "frames/holiday.png"));
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
}

TEST(FolderManifest, AListedFileBelowALinkedFolderIsNotReachedThroughIt) {
  const fs::path dir = test::fresh_test_dir(), victim = test::fresh_test_dir() / "victim";
  fs::create_directories(victim);
  touch(victim / "a.png");
  FolderManifest::read(dir).add_and_write(dir, {"frames/a.png"});
  fs::create_symlink(victim, dir / "frames");
  FolderManifest::read(dir).remove_listed(dir);
  EXPECT_TRUE(fs::exists(victim / "a.png"));
}

TEST(FolderManifest, AManifestNamingAPathOutsideTheFolderIsRefused) {
  for (const char* bad : {"../../etc/passwd", "/etc/passwd", "frames/../../x", "a/b/c"}) {
    const fs::path dir = test::fresh_test_dir();
    std::ofstream(dir / FolderManifest::kFileName) << "# gearsim\nstate.csv\n" << bad << "\n";
    try {
      FolderManifest::read(dir);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(FolderManifest::kFileName) + ":3: not a manifest of gearsim's"), std::string::npos)
          << e.what();
    }
  }
}

TEST(FolderManifest, OtherFilesAreTheOnesThatAreNeitherLockNorManifest) {
  const fs::path dir = test::fresh_test_dir();
  { const FolderLock lock(dir, "gearsim run"); }
  FolderManifest::read(dir).add_and_write(dir, {});
  EXPECT_FALSE(holds_other_files(dir));
  touch(dir / "video_of_my_cat.mp4");
  EXPECT_TRUE(holds_other_files(dir));
}

}  // namespace gearsim::test_folder
