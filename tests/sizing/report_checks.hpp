// Checks both sizing report tests make (report_test.cpp, cycle_report_test.cpp).
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace sreh::sizing::test {

// Issue 16: every inline SVG of `html` has at least six distinct numeric
// tick labels (a readable scale). Returns the number of SVGs.
inline std::size_t count_svgs_with_ticks(const std::string& html) {
  const std::regex number(R"(<text[^>]*>(-?[0-9]+(\.[0-9]+)?)</text>)");
  std::size_t svgs = 0;
  for (std::size_t a = html.find("<svg"); a != std::string::npos; a = html.find("<svg", a + 1), ++svgs) {
    const std::string svg = html.substr(a, html.find("</svg>", a) - a);
    std::set<std::string> labels;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), number); it != std::sregex_iterator(); ++it) labels.insert((*it)[1]);
    EXPECT_GE(labels.size(), 6u) << svg.substr(0, 200);
  }
  return svgs;
}

// The whole file, as written.
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

} // namespace sreh::sizing::test
