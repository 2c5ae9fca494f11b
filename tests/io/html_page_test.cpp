// The one HTML page shell (io/html_page.hpp, issue 13): every page of the
// project (run report, sizing reports, serve's live page) starts and ends
// with these bytes.
#include <gtest/gtest.h>

#include "io/html_page.hpp"

namespace sreh::io {
namespace {

TEST(HtmlPage, EscapesTheFiveMarkupCharacters) {
  EXPECT_EQ(html_escape(R"(a<b>&"c"'d')"), "a&lt;b&gt;&amp;&quot;c&quot;&#39;d&#39;");
  EXPECT_EQ(html_escape("plain text 90 deg"), "plain text 90 deg");
}

TEST(HtmlPage, WrapsHeadAndBodyInOneShellWithAnEscapedTitle) {
  const std::string page = html_page("run <1> & \"2\"", "<style>p{}</style>\n", "<p>x</p>\n");
  EXPECT_EQ(page,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<title>run &lt;1&gt; &amp; &quot;2&quot;</title>\n<style>p{}</style>\n" + std::string(kPrintCss) + "</head>\n<body>\n"
            "<p>x</p>\n</body>\n</html>\n");
  // The two halves, for pages built piece by piece, give the same bytes.
  EXPECT_EQ(html_page_open("run <1> & \"2\"", "<style>p{}</style>\n") + "<p>x</p>\n" + html_page_close(), page);
}

// Issue 29: a browser prints every page on A4 without cutting a plot.
TEST(HtmlPage, CarriesAnA4PrintStylesheetThatKeepsPlotsWhole) {
  const std::string page = html_page("t", "", "");
  const std::size_t print = page.find("<style media=\"print\">");
  ASSERT_NE(print, std::string::npos);
  EXPECT_LT(print, page.find("</head>"));
  EXPECT_NE(page.find("@page{size:A4", print), std::string::npos);
  EXPECT_NE(page.find(".fig,svg,table", print), std::string::npos);
  EXPECT_NE(page.find("break-inside:avoid", print), std::string::npos);
}

} // namespace
} // namespace sreh::io
