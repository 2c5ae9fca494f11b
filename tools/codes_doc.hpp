// docs/errors.md, generated from the one table of codes (issue 39):
// `sreh-twin codes --markdown` prints it; CTest cli.codes_doc_up_to_date
// fails when the file in the tree differs.
#pragma once
#include <string>

namespace sreh::tools {

std::string codes_markdown();

} // namespace sreh::tools
