// Output files are written whole or not at all (interfaces.md: nothing
// half-written left behind): write PATH.tmp in the same folder, then rename.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>

namespace sreh {

// Throws std::runtime_error naming the file when it cannot be written; the
// temporary file is removed then.
void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write);

// Whether a file could be created at `path` (its folder exists); checked
// before a long run so that a typo fails at once.
bool output_folder_exists(const std::string& path);

} // namespace sreh
