// One rule for every output option of every command (issue 12), checked
// before any long work starts:
//  - the parent folder must exist (nothing is created on the way);
//  - a file option must not name a folder (a trailing '/' is refused);
//    a folder option may end in '/';
//  - no output may be the same file as an input (device + inode when both
//    exist; otherwise the resolved paths), nor the same as another output.
// Errors are PathError: "OPTION PATH: what is wrong" (exit 2 in the CLI).
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace sreh::io {

struct PathError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class OutputKind {
  File,            // --trace, --video, --csv, --save-nvm: replaced atomically
  Folder,          // --report: created (one level) or reused; files inside replaced
  EmptyFolder,     // --frames: must be absent or an empty folder
};

struct Output {
  std::string option; // "--trace"
  std::string path;   // empty: option not given
  OutputKind kind = OutputKind::File;
};

// Throws PathError for the first output that breaks the rule. `inputs` are
// the files the command reads (scenario, load, NVM image, ...).
void check_outputs(const std::vector<Output>& outputs, const std::vector<std::string>& inputs);

// Whether two paths name the same file (device + inode if both exist, else
// the same resolved path).
bool same_file(const std::string& a, const std::string& b);

} // namespace sreh::io
