// `sreh-twin run DIR [--shard i/N|auto|auto/N] [--json]` (issue 17): every
// *.yaml directly in DIR, sorted by name (bytewise), the shard's contiguous
// block of them (io/shard.hpp, as `sweep --shard`). All files of the shard
// are checked before any runs (exit 2, one line per bad file); then each runs
// in turn, one line per file. Exit 0 all held, 1 any failed, 2 bad input
// (also a file the twin rejects while running; the others still run).
#pragma once
#include <string>
#include <vector>

#include "scenarios/limits.hpp"

namespace sreh::tools {

struct FolderArgs {
  std::string dir;
  std::string shard; // "" : the whole folder
  bool json = false;  // JSON Lines: one `run FILE --json` object (+ "file") per line
  Limits limits;
  std::string model; // --model FILE: model card overrides for every scenario (issue 25)
};

// The scenario files of `dir` (paths as DIR/NAME), sorted; throws InputError
// if `dir` cannot be read or holds no *.yaml.
std::vector<std::string> scenario_files(const std::string& dir);

int run_folder(const FolderArgs& args);

} // namespace sreh::tools
