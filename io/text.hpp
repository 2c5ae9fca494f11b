// Echoing user input into one-line messages (issue 12): control characters
// (newline, CR, escape, ...) and bytes that are not UTF-8 are shown escaped
// (\n, \r, \x1B), so a message stays one line and cannot drive a terminal.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace sreh::io {

std::string escape_control(std::string_view text);
bool is_valid_utf8(std::string_view text);
// Offset of the first byte that does not start a valid UTF-8 sequence, or
// std::string_view::npos when all of `text` is valid.
std::size_t first_invalid_utf8(std::string_view text);

// Levenshtein distance (insertions, deletions, substitutions): the "did you
// mean" of mistyped names (model constants, options).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The name among `names` that `given` most likely meant, or "" when none is
// close (issue 39): the same name in other letter case; a name `given` is
// the start of ("angle" -> "angle-deg"); else the nearest by edit distance
// of at most a third of the name's length (at least 1), ignoring case.
std::string closest_name(std::string_view given, const std::vector<std::string>& names);

} // namespace sreh::io
