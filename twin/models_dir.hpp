// Where the MJCF models are (issue 13: installable). The tool and programs
// linking the twin find them wherever the project was installed or built:
//   1. $SREH_TWIN_MODELS_DIR, if set (a user's own copy);
//   2. <folder of the running program>/../share/sreh_twin/models (an installed
//      tree, also after it was moved as a whole);
//   3. the install prefix this library was built for (<prefix>/share/sreh_twin/models);
//   4. the source tree it was built from (a build folder, tests).
// The first folder that holds sreh50.xml wins.
#pragma once
#include <string>

namespace sreh {

// Throws std::runtime_error listing the folders tried when none holds the model.
std::string models_dir();

} // namespace sreh
