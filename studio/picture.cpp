// The load's picture in the studio (issue 37): `load show --picture`
// (renders/load_picture.hpp) of the state's load, read back as PNG bytes.
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "renders/load_picture.hpp"
#include "studio/answer.hpp"

namespace sreh::studio {

std::string load_picture_png(const Json& state) {
  const Json s = normalised_state(state);
  if (s["parts"].empty()) throw ProjectError("picture: the load has no parts");
  const LoadSpec load = parsed_load(s).load;
  double scale = 1.0; // only the centre of mass and the mounting face are drawn: the same for scaled masses
  const LoadFigures f = load_figures_of(s, scale);
  std::string dir_template = (std::filesystem::temp_directory_path() / "sreh-studio-XXXXXX").string();
  if (mkdtemp(dir_template.data()) == nullptr) throw std::runtime_error("picture: no temporary folder");
  const std::filesystem::path dir = dir_template;
  std::string png;
  try {
    write_load_picture(load, f, (dir / "load.png").string());
    std::ifstream in(dir / "load.png", std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    png = bytes.str();
  } catch (...) {
    std::filesystem::remove_all(dir);
    throw;
  }
  std::filesystem::remove_all(dir);
  return png;
}

} // namespace sreh::studio
