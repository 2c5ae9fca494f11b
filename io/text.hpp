// Echoing user input into one-line messages (issue 12): control characters
// (newline, CR, escape, ...) and bytes that are not UTF-8 are shown escaped
// (\n, \r, \x1B), so a message stays one line and cannot drive a terminal.
#pragma once
#include <string>
#include <string_view>

namespace sreh::io {

std::string escape_control(std::string_view text);
bool is_valid_utf8(std::string_view text);
// Offset of the first byte that does not start a valid UTF-8 sequence, or
// std::string_view::npos when all of `text` is valid.
std::size_t first_invalid_utf8(std::string_view text);

// Levenshtein distance (insertions, deletions, substitutions): the "did you
// mean" of mistyped names (model constants, options).
std::size_t edit_distance(std::string_view a, std::string_view b);

} // namespace sreh::io
