#include "twin/mjcf_checks.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "twin/mujoco_support.hpp"

namespace sreh {
namespace {

constexpr int kMaxIncludeDepth = 8;

int line_of(const std::string& text, std::size_t offset) {
  int line = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

std::string expand(const std::string& text, const std::filesystem::path& dir, const std::string& origin, int depth) {
  static const std::regex include(R"re(<include\s+file\s*=\s*"([^"]*)"\s*/>)re");
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), include); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::size_t at = static_cast<std::size_t>(m.position(0));
    const std::string where = origin + ":" + std::to_string(line_of(text, at));
    if (depth >= kMaxIncludeDepth) {
      throw std::invalid_argument(where + ": <include> nested more than " + std::to_string(kMaxIncludeDepth) + " deep");
    }
    const std::filesystem::path given(m[1].str());
    const std::filesystem::path file = given.is_absolute() ? given : dir / given;
    std::string inner;
    try {
      inner = read_text_file(file.string());
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument(where + ": <include file=\"" + m[1].str() + "\">: cannot open " + file.string() +
                                  " (relative to the including file's folder)");
    }
    // MuJoCo semantics: the children of the included file's <mujoco> root.
    const std::size_t open = inner.find("<mujoco");
    const std::size_t open_end = open == std::string::npos ? open : inner.find('>', open);
    const std::size_t close = inner.rfind("</mujoco>");
    if (open_end == std::string::npos || close == std::string::npos || close < open_end) {
      throw std::invalid_argument(file.string() + ": an included file must be a <mujoco> document");
    }
    const std::string children = inner.substr(open_end + 1, close - open_end - 1);
    out += text.substr(last, at - last);
    out += expand(children, file.parent_path(), file.string(), depth + 1);
    last = at + static_cast<std::size_t>(m.length(0));
  }
  out += text.substr(last);
  return out;
}

std::string body_before(const std::string& text, std::size_t offset) {
  static const std::regex body_name(R"re(<body[^>]*\bname\s*=\s*"([^"]*)")re");
  std::string name = "(unnamed)";
  const std::string head = text.substr(0, offset);
  for (auto it = std::sregex_iterator(head.begin(), head.end(), body_name); it != std::sregex_iterator(); ++it) {
    name = (*it)[1].str();
  }
  return name;
}

} // namespace

std::string expand_mjcf_includes(const std::string& text, const std::string& dir, const std::string& origin) {
  return expand(text, dir, origin, 0);
}

void check_mjcf_inertials(const std::string& text, const std::string& origin) {
  static const std::regex element(R"re(<(inertial|geom|body|site)\b([^>]*)>)re");
  static const std::regex attribute(R"re(\b(mass|diaginertia|fullinertia|density)\s*=\s*"([^"]*)")re");
  for (auto e = std::sregex_iterator(text.begin(), text.end(), element); e != std::sregex_iterator(); ++e) {
    const std::string tag = (*e)[1].str();
    const std::string attrs = (*e)[2].str();
    for (auto a = std::sregex_iterator(attrs.begin(), attrs.end(), attribute); a != std::sregex_iterator(); ++a) {
      const std::string name = (*a)[1].str();
      std::istringstream values((*a)[2].str());
      std::string word;
      while (values >> word) {
        const auto where = [&] {
          return origin + ":" + std::to_string(line_of(text, static_cast<std::size_t>(e->position(0)))) + ": body '" +
                 body_before(text, static_cast<std::size_t>(e->position(0))) + "': <" + tag + " " + name + "> " + word;
        };
        errno = 0;
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (end == word.c_str() || *end != '\0') continue; // not a number: MuJoCo's parser reports it
        const bool underflow = errno == ERANGE && std::abs(v) < 1.0;
        if (!std::isfinite(v)) throw std::invalid_argument(where() + " is not finite");
        if (name == "fullinertia") {
          if (underflow || std::fpclassify(v) == FP_SUBNORMAL) throw std::invalid_argument(where() + " is too small to model");
          continue; // off-diagonal terms may be negative
        }
        if (v < 0) throw std::invalid_argument(where() + " is negative");
        if (underflow || std::fpclassify(v) == FP_SUBNORMAL) {
          throw std::invalid_argument(where() + " is too small to model (subnormal)");
        }
        if (tag == "inertial" && v == 0) throw std::invalid_argument(where() + ": an <inertial> needs a mass and inertia above 0");
      }
    }
  }
}

void check_compiled_inertials(const mjModel* m, const std::string& origin) {
  for (int b = 1; b < m->nbody; ++b) {
    const char* name = mj_id2name(m, mjOBJ_BODY, b);
    const std::string body = origin + ": body '" + (name ? name : "(unnamed)") + "': ";
    const double values[4] = {m->body_mass[b], m->body_inertia[3 * b], m->body_inertia[3 * b + 1], m->body_inertia[3 * b + 2]};
    for (int k = 0; k < 4; ++k) {
      const double v = values[k];
      const char* what = k == 0 ? "mass" : "inertia";
      if (!std::isfinite(v)) throw std::invalid_argument(body + what + " from its geoms is not finite (" + std::to_string(v) + ")");
      if (v < 0) throw std::invalid_argument(body + what + " is negative");
      if (std::fpclassify(v) == FP_SUBNORMAL) throw std::invalid_argument(body + what + " is too small to model (subnormal)");
    }
  }
}

} // namespace sreh
