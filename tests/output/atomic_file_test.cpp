// Result files are replaced whole or not at all.

#include "signorini/output/atomic_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "expect_contains.hpp"
#include "signorini/core/error.hpp"
#include "temporary_folder.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, WritesAndReplaces) {
  const testing::TemporaryFolder dir;
  const fs::path file = dir / "summary.json";
  write_file_atomically(file, "first\n");
  EXPECT_EQ(read(file), "first\n");
  write_file_atomically(file, "second, longer\n");
  EXPECT_EQ(read(file), "second, longer\n");
  write_file_atomically(file, "");
  EXPECT_EQ(read(file), "");
  EXPECT_EQ(count_entries(dir.path()), 1U);  // no temporary left behind
}

TEST(AtomicFile, FailedWriteLeavesTheEarlierFileIntact) {
  const testing::TemporaryFolder dir;
  const fs::path file = dir / "contact.csv";
  write_file_atomically(file, "earlier results\n");
  // A folder where the new contents cannot be placed: the rename fails after the temporary file
  // was written, which is the last moment anything can go wrong.
  const fs::path blocked = dir / "blocked";
  fs::create_directories(blocked / "not_empty");
  EXPECT_THROW(write_file_atomically(blocked, "new"), InputError);
  EXPECT_EQ(read(file), "earlier results\n");
  EXPECT_EQ(count_entries(dir.path()), 2U);  // contact.csv and blocked/, no temporary
}

TEST(AtomicFile, UnwritableFolderKeepsTheFileAndNamesThePath) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write anywhere";
  const testing::TemporaryFolder dir;
  const fs::path file = dir / "summary.json";
  write_file_atomically(file, "earlier\n");
  fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
  try {
    write_file_atomically(file, "new\n");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "cannot write '" + file.string() + "': ");
  }
  fs::permissions(dir.path(), fs::perms::owner_all);
  EXPECT_EQ(read(file), "earlier\n");
}

TEST(AtomicFile, MissingFolderIsAnError) {
  const testing::TemporaryFolder dir;
  const fs::path file = dir / "no_such_folder" / "summary.json";
  try {
    write_file_atomically(file, "x");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "cannot write '" + file.string() + "': No such file");
  }
}

TEST(AtomicFile, SeveralFilesAreReplacedTogether) {
  const testing::TemporaryFolder dir;
  write_files_atomically({{dir / "a.json", "new a\n"}, {dir / "b.csv", "new b\n"}});
  EXPECT_EQ(read(dir / "a.json"), "new a\n");
  EXPECT_EQ(read(dir / "b.csv"), "new b\n");
  EXPECT_EQ(count_entries(dir.path()), 2U);
  // The second file cannot be written: the first keeps its earlier contents too, and no
  // temporary is left behind.
  const fs::path missing = dir / "no_such_folder" / "c.vtu";
  try {
    write_files_atomically({{dir / "a.json", "newer a\n"}, {missing, "c\n"}});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "cannot write '" + missing.string() + "': No such file");
  }
  EXPECT_EQ(read(dir / "a.json"), "new a\n");
  EXPECT_EQ(count_entries(dir.path()), 2U);
}

}  // namespace
}  // namespace signorini
