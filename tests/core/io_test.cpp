#include <gtest/gtest.h>

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

}  // namespace
}  // namespace swarf
