#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/parse_error.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;
using namespace foldkit;

std::size_t entries(const std::string& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicWrite, ReplacesAndLeavesNoTemporary) {
  const std::string dir = test::temp_dir();
  io::write_file_atomic(dir + "/a.txt", "one");
  io::write_file_atomic(dir + "/a.txt", "two");
  EXPECT_EQ(io::read_file(dir + "/a.txt"), "two");
  EXPECT_EQ(entries(dir), 1u);
}

TEST(AtomicWrite, LongestNameFits) {
  const std::string dir = test::temp_dir();
  const std::string name = dir + "/" + std::string(250, 'n') + ".fold";
  io::write_file_atomic(name, "x");
  EXPECT_EQ(io::read_file(name), "x");
}

TEST(AtomicWrite, FollowsSymlinkAndKeepsPermissions) {
  const std::string dir = test::temp_dir();
  io::write_file_atomic(dir + "/real.txt", "old");
  ASSERT_EQ(::chmod((dir + "/real.txt").c_str(), 0600), 0);
  fs::create_symlink(dir + "/real.txt", dir + "/link.txt");
  io::write_file_atomic(dir + "/link.txt", "new");
  EXPECT_TRUE(fs::is_symlink(dir + "/link.txt"));
  EXPECT_EQ(io::read_file(dir + "/real.txt"), "new");
  struct stat st {};
  ASSERT_EQ(::stat((dir + "/real.txt").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0600u);
}

TEST(AtomicWrite, FailureIsAWriteErrorAndLeavesNothing) {
  const std::string dir = test::temp_dir();
  try {
    io::write_file_atomic(dir + "/missing/x.txt", "x");
    FAIL();
  } catch (const io::WriteError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(dir + "/missing/x.txt: cannot write: ", 0), 0u) << e.what();
  }
  fs::create_directory(dir + "/target");
  EXPECT_THROW(io::write_file_atomic(dir + "/target", "x"), io::WriteError);  // a directory
  EXPECT_TRUE(fs::is_directory(dir + "/target"));
  EXPECT_EQ(entries(dir), 1u);
}

TEST(ReadFile, MissingAndDirectory) {
  const std::string dir = test::temp_dir();
  EXPECT_THROW(io::read_file(dir + "/nope"), io::ParseError);
  EXPECT_THROW(io::read_file(dir), io::ParseError);
}

// A missing file is nothing (a file the command makes); one that is there reads as read_file(),
// a directory too (a ParseError), compressed or not.
TEST(ReadFile, IfPresent) {
  const std::string dir = test::temp_dir();
  fs::remove(dir + "/absent.db");
  EXPECT_FALSE(io::read_file_if_present(dir + "/absent.db").has_value());
  io::write_file_atomic(dir + "/present.db", "abc");
  EXPECT_EQ(io::read_file_if_present(dir + "/present.db").value_or("?"), "abc");
  io::write_file_atomic(dir + "/present.db.gz", "abc");
  EXPECT_EQ(io::read_file_if_present(dir + "/present.db.gz").value_or("?"), "abc");
  EXPECT_THROW(io::read_file_if_present(dir), io::ParseError);
}

}  // namespace
