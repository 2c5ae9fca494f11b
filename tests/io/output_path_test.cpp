// io::check_outputs (issue 12): one rule for every output option.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/output_path.hpp"

namespace fs = std::filesystem;
using sreh::io::check_outputs;
using sreh::io::OutputKind;
using sreh::io::PathError;

namespace {

class OutputPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sreh_out_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(p("scenario.yaml")) << "name: x\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string p(const std::string& name) const { return (dir_ / name).string(); }
  std::string error(const std::vector<sreh::io::Output>& outs, const std::vector<std::string>& ins = {}) const {
    try {
      check_outputs(outs, ins);
    } catch (const PathError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(OutputPathTest, AcceptsNewFilesAndFolders) {
  EXPECT_EQ(error({{"--trace", p("t.csv"), OutputKind::File}, {"--report", p("rep/"), OutputKind::Folder},
                   {"--frames", p("frames"), OutputKind::EmptyFolder}, {"--video", "", OutputKind::File}},
                  {p("scenario.yaml")}),
            "");
}

TEST_F(OutputPathTest, MissingParentNamesTheOption) {
  EXPECT_NE(error({{"--report", p("no/rep"), OutputKind::Folder}}).find("--report"), std::string::npos);
  EXPECT_NE(error({{"--csv", p("no/x.csv"), OutputKind::File}}).find("does not exist"), std::string::npos);
}

TEST_F(OutputPathTest, FileOptionsRefuseFolders) {
  fs::create_directory(p("dir"));
  EXPECT_NE(error({{"--video", p("dir"), OutputKind::File}}).find("is a folder"), std::string::npos);
  EXPECT_NE(error({{"--trace", p("t.csv/"), OutputKind::File}}).find("names a folder"), std::string::npos);
}

TEST_F(OutputPathTest, FramesMustBeAbsentOrEmpty) {
  fs::create_directory(p("frames"));
  EXPECT_EQ(error({{"--frames", p("frames"), OutputKind::EmptyFolder}}), "");
  std::ofstream(p("frames/x.png")) << "x";
  EXPECT_NE(error({{"--frames", p("frames"), OutputKind::EmptyFolder}}).find("not empty"), std::string::npos);
  EXPECT_NE(error({{"--report", p("scenario.yaml"), OutputKind::Folder}}).find("not a folder"), std::string::npos);
}

TEST_F(OutputPathTest, RefusesAnInputAsOutputAlsoThroughOtherNames) {
  EXPECT_NE(error({{"--trace", p("scenario.yaml"), OutputKind::File}}, {p("scenario.yaml")}).find("input file"),
            std::string::npos);
  const std::string dotted = (dir_ / "." / "scenario.yaml").string();
  EXPECT_NE(error({{"--trace", dotted, OutputKind::File}}, {p("scenario.yaml")}), "");
  fs::create_symlink(p("scenario.yaml"), p("link.yaml"));
  EXPECT_NE(error({{"--save-nvm", p("link.yaml"), OutputKind::File}}, {p("scenario.yaml")}), "");
  fs::create_hard_link(p("scenario.yaml"), p("hard.yaml"));
  EXPECT_NE(error({{"--trace", p("hard.yaml"), OutputKind::File}}, {p("scenario.yaml")}), "");
}

TEST_F(OutputPathTest, RefusesTwoOutputsOnOneFile) {
  EXPECT_NE(error({{"--trace", p("x"), OutputKind::File}, {"--save-nvm", p("./x"), OutputKind::File}})
                .find("also the output of --trace"),
            std::string::npos);
}

} // namespace
