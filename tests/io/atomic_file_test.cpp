// io::AtomicFile / AtomicDir (issue 12): whole or nothing, unique temporary
// names, never through a link.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/atomic_file.hpp"

namespace fs = std::filesystem;
using sreh::io::AtomicDir;
using sreh::io::AtomicFile;
using sreh::io::write_file_atomic;

namespace {

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sreh_io_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string read(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }
  fs::path dir_;
};

using AtomicFileTest = TempDir;

TEST_F(AtomicFileTest, WritesTheWholeFileOnCommit) {
  write_file_atomic(path("out.csv"), [](std::ostream& out) { out << "a,b\n1,2\n"; });
  EXPECT_EQ(read(path("out.csv")), "a,b\n1,2\n");
  EXPECT_EQ(entries(), 1u); // no temporary left
}

TEST_F(AtomicFileTest, LeavesNothingWhenTheWriterThrows) {
  std::ofstream(path("out.csv")) << "old";
  EXPECT_THROW(write_file_atomic(path("out.csv"),
                                 [](std::ostream& out) {
                                   out << "half";
                                   throw std::runtime_error("boom");
                                 }),
               std::runtime_error);
  EXPECT_EQ(read(path("out.csv")), "old");
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, TemporaryIsUniqueAndInTheTargetsFolder) {
  AtomicFile a(path("out.csv"));
  AtomicFile b(path("out.csv"));
  EXPECT_NE(a.temp_path(), b.temp_path());
  EXPECT_EQ(fs::path(a.temp_path()).parent_path(), dir_);
  EXPECT_TRUE(fs::exists(a.temp_path()));
}

TEST_F(AtomicFileTest, DestructorRemovesAnUncommittedTemporary) {
  std::string temp;
  {
    AtomicFile f(path("out.csv"));
    f.stream() << "x";
    temp = f.temp_path();
  }
  EXPECT_FALSE(fs::exists(temp));
  EXPECT_FALSE(fs::exists(path("out.csv")));
}

TEST_F(AtomicFileTest, ReplacesASymlinkInsteadOfWritingThroughIt) {
  std::ofstream(path("victim")) << "precious";
  fs::create_symlink(path("victim"), path("out.csv"));
  write_file_atomic(path("out.csv"), [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(read(path("victim")), "precious");
  EXPECT_FALSE(fs::is_symlink(path("out.csv")));
  EXPECT_EQ(read(path("out.csv")), "new");
}

TEST_F(AtomicFileTest, OldFixedTemporaryNameIsNotFollowed) {
  // The old writers used "<out>.tmp": a link planted there redirected the write.
  std::ofstream(path("victim")) << "precious";
  fs::create_symlink(path("victim"), path("out.csv.tmp"));
  write_file_atomic(path("out.csv"), [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(read(path("victim")), "precious");
  EXPECT_EQ(read(path("out.csv")), "new");
}

TEST_F(AtomicFileTest, MissingFolderThrowsNamingThePath) {
  try {
    AtomicFile f(path("no/such/out.csv"));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/out.csv"), std::string::npos) << e.what();
  }
}

TEST_F(AtomicFileTest, TellpCountsTheBytesWritten) {
  AtomicFile f(path("out.csv"));
  f.stream() << "12345";
  EXPECT_EQ(static_cast<long>(f.stream().tellp()), 5);
}

using AtomicDirTest = TempDir;

TEST_F(AtomicDirTest, CommitReplacesAnEmptyFolder) {
  fs::create_directory(path("frames"));
  AtomicDir d(path("frames/"));
  std::ofstream(fs::path(d.temp_path()) / "frame_000000.png") << "png";
  d.commit();
  EXPECT_TRUE(fs::exists(fs::path(path("frames")) / "frame_000000.png"));
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicDirTest, UncommittedFolderIsRemoved) {
  {
    AtomicDir d(path("frames"));
    std::ofstream(fs::path(d.temp_path()) / "frame_000000.png") << "png";
  }
  EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicDirTest, MakeOutputFolderCreatesOneLevelOnly) {
  EXPECT_NO_THROW(sreh::io::make_output_folder(path("rep/")));
  EXPECT_TRUE(fs::is_directory(path("rep")));
  EXPECT_THROW(sreh::io::make_output_folder(path("a/b")), std::runtime_error);
  EXPECT_FALSE(fs::exists(path("a")));
}

} // namespace
