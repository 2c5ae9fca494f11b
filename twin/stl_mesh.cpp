#include "twin/stl_mesh.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "twin/mujoco_support.hpp"

namespace sreh {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50; // normal, 3 vertices (12 floats), attribute count
constexpr std::size_t kMaxTriangles = 200000; // MuJoCo 2.2.2's limit for STL faces

bool looks_ascii(const std::string& bytes) {
  if (bytes.compare(0, 5, "solid") != 0) return false;
  // Some binary files start with "solid" too: their size gives them away.
  if (bytes.size() >= kHeaderBytes + 4) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + kHeaderBytes, 4);
    if (bytes.size() == kHeaderBytes + 4 + kTriangleBytes * static_cast<std::size_t>(n)) return false;
  }
  return true;
}

StlMesh parse_ascii(const std::string& bytes, const std::string& path) {
  StlMesh mesh;
  std::istringstream in(bytes);
  std::string word;
  std::array<float, 9> tri{};
  int vertex = 0;
  int line_words = 0;
  while (in >> word) {
    ++line_words;
    if (word == "vertex") {
      if (vertex >= 3) throw std::invalid_argument(path + ": ASCII STL facet with more than 3 vertices");
      double xyz[3];
      for (double& c : xyz) {
        if (!(in >> c) || !std::isfinite(c)) {
          throw std::invalid_argument(path + ": ASCII STL vertex needs three finite numbers");
        }
      }
      for (int k = 0; k < 3; ++k) tri[static_cast<std::size_t>(3 * vertex + k)] = static_cast<float>(xyz[k]);
      ++vertex;
    } else if (word == "endfacet") {
      if (vertex != 3) throw std::invalid_argument(path + ": ASCII STL facet without 3 vertices");
      mesh.triangles.push_back(tri);
      vertex = 0;
    }
  }
  if (line_words == 0 || mesh.triangles.empty()) throw std::invalid_argument(path + ": STL file has no triangles");
  return mesh;
}

StlMesh parse_binary(const std::string& bytes, const std::string& path) {
  if (bytes.size() < kHeaderBytes + 4) throw std::invalid_argument(path + ": not an STL file (too short)");
  std::uint32_t n = 0;
  std::memcpy(&n, bytes.data() + kHeaderBytes, 4);
  if (n == 0) throw std::invalid_argument(path + ": STL file has no triangles");
  if (bytes.size() < kHeaderBytes + 4 + kTriangleBytes * static_cast<std::size_t>(n)) {
    throw std::invalid_argument(path + ": binary STL announces " + std::to_string(n) + " triangles but is shorter");
  }
  StlMesh mesh;
  mesh.triangles.resize(n);
  for (std::size_t t = 0; t < n; ++t) {
    const char* p = bytes.data() + kHeaderBytes + 4 + kTriangleBytes * t + 12; // skip the normal
    std::memcpy(mesh.triangles[t].data(), p, 36);
    for (float c : mesh.triangles[t]) {
      if (!std::isfinite(c)) throw std::invalid_argument(path + ": STL vertex coordinate is not finite");
    }
  }
  return mesh;
}

} // namespace

StlMesh parse_stl(const std::string& bytes, const std::string& path) {
  StlMesh mesh = looks_ascii(bytes) ? parse_ascii(bytes, path) : parse_binary(bytes, path);
  if (mesh.triangles.size() > kMaxTriangles) {
    throw std::invalid_argument(path + ": " + std::to_string(mesh.triangles.size()) + " triangles, more than MuJoCo's " +
                                std::to_string(kMaxTriangles));
  }
  return mesh;
}

StlMesh read_stl_file(const std::string& path) { return parse_stl(read_text_file(path), path); }

double stl_volume(const StlMesh& mesh) {
  double six_v = 0; // sum of signed tetrahedra against the origin
  for (const auto& t : mesh.triangles) {
    const double ax = t[0], ay = t[1], az = t[2], bx = t[3], by = t[4], bz = t[5], cx = t[6], cy = t[7], cz = t[8];
    six_v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  }
  return six_v / 6;
}

void check_closed_mesh(const StlMesh& mesh, const std::string& path) {
  using Vertex = std::tuple<float, float, float>;
  std::map<Vertex, int> ids;
  auto id_of = [&](const auto& t, int k) {
    const Vertex v{t[static_cast<std::size_t>(3 * k)], t[static_cast<std::size_t>(3 * k + 1)],
                   t[static_cast<std::size_t>(3 * k + 2)]};
    return ids.emplace(v, static_cast<int>(ids.size())).first->second;
  };
  // A directed edge a->b: in a closed, consistently oriented surface each
  // appears once, and b->a once.
  std::map<std::pair<int, int>, int> directed;
  std::size_t degenerate = 0;
  for (const auto& t : mesh.triangles) {
    const int v[3] = {id_of(t, 0), id_of(t, 1), id_of(t, 2)};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) { ++degenerate; continue; }
    for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    const int opposite = back == directed.end() ? 0 : back->second;
    if (count != 1 || opposite != 1) {
      throw std::invalid_argument(path + ": the mesh is not closed (an edge belongs to " + std::to_string(count + opposite) +
                                  " triangles, or they disagree in orientation): a load mesh must be a watertight solid");
    }
  }
  if (degenerate == mesh.triangles.size()) throw std::invalid_argument(path + ": every triangle of the mesh is degenerate");
  const double v = stl_volume(mesh);
  if (!(v > 0)) {
    throw std::invalid_argument(path + ": the mesh encloses no volume (degenerate, or its normals point inward)");
  }
}

std::string binary_stl(const StlMesh& mesh) {
  std::string out(kHeaderBytes + 4 + kTriangleBytes * mesh.triangles.size(), '\0');
  const std::string header = "sreh-twin binary STL";
  std::memcpy(out.data(), header.data(), header.size());
  const auto n = static_cast<std::uint32_t>(mesh.triangles.size());
  std::memcpy(out.data() + kHeaderBytes, &n, 4);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::memcpy(out.data() + kHeaderBytes + 4 + kTriangleBytes * t + 12, mesh.triangles[t].data(), 36);
  }
  return out;
}

} // namespace sreh
