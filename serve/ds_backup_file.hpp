// The master's Data Storage backup as a file in serve's state folder
// (port<P>.ds.json): JSON, values as hex (serve/state_dir.hpp).
#pragma once
#include <string>

#include "scenarios/data_storage_master.hpp"

namespace sreh::serve {

// `download_owed`: a replaced module has not got the backup yet (issue 40:
// the next start downloads it, whenever serve was stopped or killed).
std::string ds_backup_json(const DsBackup& backup, bool download_owed);
// Throws std::invalid_argument (message without a file name) if malformed.
DsBackup ds_backup_from_json(const std::string& text, bool* download_owed = nullptr);

} // namespace sreh::serve
