#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "swarf/core/io.h"

namespace swarf {
namespace {

namespace fs = std::filesystem;

class IoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("swarf_io_test_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(IoTest, WriteCreatesParentFoldersAndRoundTripsBinary) {
  const std::string path = (dir_ / "a" / "b" / "out.bin").string();
  std::string content = "line 1\n";
  content.push_back('\0');
  content += "\xff\r\nend";
  ASSERT_TRUE(write_file_atomic(path, content).ok());
  const Result<std::string> back = read_file(path);
  ASSERT_TRUE(back.ok()) << back.status().to_string();
  EXPECT_EQ(*back, content);
}

TEST_F(IoTest, WriteReplacesAndLeavesNoTemporaryFiles) {
  const std::string path = (dir_ / "out.txt").string();
  ASSERT_TRUE(write_file_atomic(path, "first, longer content").ok());
  ASSERT_TRUE(write_file_atomic(path, "second").ok());
  EXPECT_EQ(*read_file(path), "second");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) {
    (void)e;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST_F(IoTest, EmptyContentMakesEmptyFile) {
  const std::string path = (dir_ / "empty").string();
  ASSERT_TRUE(write_file_atomic(path, "").ok());
  EXPECT_EQ(*read_file(path), "");
}

TEST_F(IoTest, MissingFileIsIoErrorNamingThePath) {
  const std::string path = (dir_ / "nope.stl").string();
  const Result<std::string> r = read_file(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), Error::kIo);
  EXPECT_NE(r.status().message().find("nope.stl"), std::string::npos);
}

TEST_F(IoTest, WritingOverAFolderFailsAndKeepsIt) {
  fs::create_directories(dir_ / "folder");
  const Status s = write_file_atomic((dir_ / "folder").string(), "x");
  EXPECT_EQ(s.code(), Error::kIo);
  EXPECT_TRUE(fs::is_directory(dir_ / "folder"));
  EXPECT_EQ(read_file((dir_ / "folder").string()).status().code(), Error::kIo);
}

// `-o /dev/null` and named pipes: the device is written, not replaced by a file renamed over
// it (as root that replaced /dev/null itself). A pipe stands in for the device here, so that
// a failure cannot break the machine the tests run on.
TEST_F(IoTest, APipeIsWrittenInPlaceAndStaysAPipe) {
  fs::create_directories(dir_);
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Held open for reading and writing, so that opening it to write does not wait for a
  // reader, and it can be read here without waiting for a writer.
  const int fd = ::open(fifo.c_str(), O_RDWR | O_NONBLOCK);
  ASSERT_GE(fd, 0);
  const Status s = write_file_atomic(fifo.string(), "G0 X1\n");
  EXPECT_TRUE(s.ok()) << s.to_string();
  char buf[64];
  const ssize_t n = ::read(fd, buf, sizeof buf);
  ::close(fd);
  EXPECT_EQ(std::string(buf, static_cast<std::size_t>(std::max<ssize_t>(n, 0))), "G0 X1\n");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

// A link to the output is kept: the file it names gets the new content.
TEST_F(IoTest, ALinkIsFollowedAndKept) {
  fs::create_directories(dir_ / "real");
  const fs::path file = dir_ / "real" / "out.nc", link = dir_ / "out.nc";
  ASSERT_TRUE(write_file_atomic(file.string(), "old").ok());
  fs::create_symlink(file, link);
  ASSERT_TRUE(write_file_atomic(link.string(), "new").ok());
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(*read_file(file.string()), "new");
}

}  // namespace
}  // namespace swarf
