// --state-dir files (issue 27): round trip, missing = factory-new, a corrupt
// file refused by name and left alone, one serve per folder; and the bearer
// scheme is case-insensitive.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "serve/http_auth.hpp"
#include "serve/state_dir.hpp"
#include "twin/twin.hpp"

namespace sreh::serve {
namespace {

namespace fs = std::filesystem;

struct StateDirTest : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("sreh-state-" + std::to_string(::getpid()) + "-" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }
  std::vector<uint8_t> commissioned() {
    Twin t{TwinConfig{}};
    const uint8_t load[] = {0x04, 0x4C}; // 1100 g cm^2 into set 1's load... any stored value
    EXPECT_TRUE(t.isdu_write(64, 4, load).ok());
    return t.save_nvm();
  }
};

TEST_F(StateDirTest, MissingFilesAreFactoryNewAndSavesComeBack) {
  {
    StateDir s(dir.string(), 2);
    const PortState first = s.load(1);
    EXPECT_FALSE(first.nvm.has_value());
    EXPECT_FALSE(first.flange_angle_deg.has_value());
    s.save(1, commissioned(), 300.0);
  }
  StateDir s(dir.string(), 2);
  const PortState again = s.load(1);
  ASSERT_TRUE(again.nvm.has_value());
  EXPECT_EQ(*again.nvm, commissioned());
  EXPECT_DOUBLE_EQ(again.flange_angle_deg.value(), 300.0);
  EXPECT_FALSE(s.load(2).nvm.has_value());
}

TEST_F(StateDirTest, CorruptImageIsRefusedByNameAndLeftAlone) {
  auto image = commissioned();
  image[image.size() / 2] ^= 0x40;
  { std::ofstream(dir / "port1.nvm", std::ios::binary).write(reinterpret_cast<const char*>(image.data()), static_cast<std::streamsize>(image.size())); }
  StateDir s(dir.string(), 1);
  try {
    s.load(1);
    FAIL() << "a corrupt image was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("port1.nvm"), std::string::npos) << e.what();
  }
  EXPECT_EQ(fs::file_size(dir / "port1.nvm"), image.size());
  { std::ofstream(dir / "port1.flange.json") << "{\"flange_angle_deg\": \"north\"}"; }
  fs::remove(dir / "port1.nvm");
  EXPECT_THROW(s.load(1), std::invalid_argument);
  fs::remove(dir / "port1.flange.json");
  { std::ofstream(dir / "port1.ds.json") << "{\"checksum\": 1, \"values\": [{\"index\": 64}]}"; }
  try {
    s.load(1);
    FAIL() << "a corrupt Data Storage backup was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("port1.ds.json"), std::string::npos) << e.what();
  }
}

TEST_F(StateDirTest, OneServePerFolder) {
  StateDir first(dir.string(), 1);
  EXPECT_THROW(StateDir(dir.string(), 1), std::invalid_argument);
  EXPECT_THROW(StateDir((dir / "nothing").string(), 1), std::invalid_argument);
}

TEST(NvmImage, SoundOnlyWhenTheDeviceTakesItBackUnchanged) {
  Twin t{TwinConfig{}};
  auto image = t.save_nvm();
  EXPECT_TRUE(nvm_image_sound(image));
  image.back() ^= 1;
  EXPECT_FALSE(nvm_image_sound(image));
  EXPECT_FALSE(nvm_image_sound({}));
}

TEST(Bearer, SchemeIsCaseInsensitiveTokenIsNot) {
  EXPECT_TRUE(bearer_matches("Bearer s3cret", "s3cret"));
  EXPECT_TRUE(bearer_matches("bearer s3cret", "s3cret"));
  EXPECT_TRUE(bearer_matches("BEARER  s3cret", "s3cret"));
  EXPECT_FALSE(bearer_matches("Bearer S3CRET", "s3cret"));
  EXPECT_FALSE(bearer_matches("Bearer s3cre", "s3cret"));
  EXPECT_FALSE(bearer_matches("Basic s3cret", "s3cret"));
  EXPECT_FALSE(bearer_matches("Bearers3cret", "s3cret"));
}

} // namespace
} // namespace sreh::serve
