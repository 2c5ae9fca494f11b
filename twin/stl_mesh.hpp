// STL meshes for loads (issue 28): MuJoCo 2.2.2 reads binary STL only and
// accepts open meshes, whose volume (and so mass and inertia) is
// meaningless. The twin reads ASCII and binary STL itself, checks that the
// surface is closed and encloses a volume, and hands MuJoCo binary STL
// through its virtual file system.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace sreh {

struct StlMesh {
  std::vector<std::array<float, 9>> triangles; // three vertices each, in the file's units
};

// Reads an ASCII or binary STL file. Throws std::invalid_argument
// "<path>: ..." for an unreadable, malformed or empty file.
StlMesh read_stl_file(const std::string& path);
StlMesh parse_stl(const std::string& bytes, const std::string& path);

// The enclosed volume in the file's units cubed (positive for outward normals).
double stl_volume(const StlMesh& mesh);

// Closed (every edge shared by exactly two triangles, in opposite
// directions) and enclosing a positive volume. Throws std::invalid_argument
// "<path>: ..." naming what is wrong.
void check_closed_mesh(const StlMesh& mesh, const std::string& path);

// The mesh as binary STL bytes (what MuJoCo 2.2.2 reads).
std::string binary_stl(const StlMesh& mesh);

} // namespace sreh
