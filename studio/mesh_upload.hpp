// STL upload in the studio's load builder (issue 37): a mesh part's file is
// sent by the page, checked as the load parser will read it (ASCII or
// binary STL, closed, enclosing a volume: twin/stl_mesh.hpp) and stored in
// the project's folder, so the exported project names it and `size --load`
// and `studio PROJECT.yaml` read it again (docs/studio.md "STL meshes").
#pragma once
#include <cstddef>
#include <string>

namespace sreh::studio {

// The largest upload: a binary STL of MuJoCo's 200000 triangles is 10 MB,
// the same in ASCII several times that; 16 MB keeps a request's memory bounded.
inline constexpr std::size_t kMaxMeshUploadBytes = 16u << 20;

// Where uploads go: the folder `meshes` next to the project file, or in the
// folder the studio was started in for a new project (absolute).
std::string mesh_folder(const std::string& project_file);

struct StoredMesh {
  std::string path;      // absolute: the exported project is saved wherever the browser puts it
  std::size_t triangles; // as read
  double volume;         // enclosed, in the file's units cubed
};

// Checks `bytes` (the file `name` the user picked) and stores it in `folder`
// (created if missing) as NAME.stl with the name reduced to letters, digits,
// '-', '_' and '.'; a different file of that name already there gets a
// suffix (-2, -3, ...), the same file is reused. Written whole or not at all.
// Throws ProjectError "NAME: what is wrong" (too big, not STL, not closed, ...).
StoredMesh store_mesh(const std::string& name, const std::string& bytes, const std::string& folder);

} // namespace sreh::studio
