// io::Spool (issue 12): a temporary for output that grows with run length,
// with no name in any folder (nothing to plant, follow or leave behind).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "io/spool.hpp"

namespace sreh::io {
namespace {

namespace fs = std::filesystem;

TEST(Spool, CopiesWhatWasWrittenAndStaysWritable) {
  Spool spool;
  std::string big(200000, 'x'); // more than the write buffer
  spool.stream() << "head\n" << big;
  EXPECT_EQ(spool.bytes(), 5u + big.size());
  std::ostringstream out;
  spool.copy_to(out);
  EXPECT_EQ(out.str(), "head\n" + big);
  spool.stream() << "tail";
  std::ostringstream again;
  spool.copy_to(again);
  EXPECT_EQ(again.str(), "head\n" + big + "tail");
}

TEST(Spool, ReadsBackWhatWasWrittenAtAnyOffsetEvenStillBuffered) {
  Spool spool;
  std::string big(100000, 'a');
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>('a' + i % 26);
  spool.stream() << big; // partly still in the write buffer
  char got[6] = {};
  spool.read_at(99995, got, 5);
  EXPECT_EQ(std::string(got, 5), big.substr(99995, 5));
  spool.read_at(0, got, 3);
  EXPECT_EQ(std::string(got, 3), "abc");
  spool.stream() << "tail"; // still writable after reading
  spool.read_at(big.size(), got, 4);
  EXPECT_EQ(std::string(got, 4), "tail");
  EXPECT_THROW(spool.read_at(big.size() + 2, got, 3), std::runtime_error); // past the end
}

TEST(Spool, LeavesNoNameInTheTemporaryFolder) {
  const fs::path dir = fs::temp_directory_path() / ("sreh_spool_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  ::setenv("TMPDIR", dir.c_str(), 1);
  {
    Spool spool;
    spool.stream() << "data";
    EXPECT_TRUE(fs::is_empty(dir)); // while open, too
  }
  EXPECT_TRUE(fs::is_empty(dir));
  // A folder that does not exist: one error naming it and how to choose another.
  ::setenv("TMPDIR", (dir / "missing").c_str(), 1);
  try {
    Spool spool;
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "missing").string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("TMPDIR"), std::string::npos) << e.what();
  }
  if (old) ::setenv("TMPDIR", saved.c_str(), 1);
  else ::unsetenv("TMPDIR");
  fs::remove_all(dir);
}

} // namespace
} // namespace sreh::io
