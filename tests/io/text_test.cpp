// io::escape_control / UTF-8 checks (issue 12).
#include <gtest/gtest.h>

#include "io/text.hpp"

using sreh::io::escape_control;
using sreh::io::first_invalid_utf8;

TEST(EscapeControl, EscapesNewlinesCarriageReturnsAndEscape) {
  EXPECT_EQ(escape_control("a\nb\rc\x1b[31m"), "a\\nb\\rc\\x1B[31m");
  EXPECT_EQ(escape_control(std::string("nul\0x", 5)), "nul\\x00x");
  EXPECT_EQ(escape_control("tab\tdel\x7f"), "tab\\tdel\\x7F");
}

TEST(EscapeControl, KeepsUtf8AndEscapesInvalidBytes) {
  EXPECT_EQ(escape_control("Drehübung 90°"), "Drehübung 90°");
  EXPECT_EQ(escape_control("Dreh\xfc"), "Dreh\\xFC");
  EXPECT_EQ(escape_control(escape_control("a\nb")), "a\\nb"); // idempotent
}

TEST(Utf8, FindsTheFirstInvalidByte) {
  EXPECT_EQ(first_invalid_utf8("plain"), std::string_view::npos);
  EXPECT_EQ(first_invalid_utf8("ok \xff"), 3u);
  EXPECT_EQ(first_invalid_utf8("\xc0\xaf"), 0u);         // overlong '/'
  EXPECT_EQ(first_invalid_utf8("\xed\xa0\x80"), 0u);     // surrogate
  EXPECT_EQ(first_invalid_utf8("\xe2\x82"), 0u);         // truncated
  EXPECT_EQ(first_invalid_utf8("\xf0\x9f\x98\x80"), std::string_view::npos);
}
