#include "twin/mjcf_namespace.hpp"

#include <regex>
#include <set>

namespace sreh {

std::string prefix_mjcf_names(const std::string& text, const std::string& prefix) {
  static const std::regex name_attr(R"re(\bname(\s*=\s*")([^"]*)")re");
  static const std::regex ref_attr(R"re(\b(material|mesh|texture|hfield)(\s*=\s*")([^"]*)")re");
  std::set<std::string> defined;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), name_attr); it != std::sregex_iterator(); ++it) {
    defined.insert((*it)[2].str());
  }
  std::string named;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), name_attr); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    named += text.substr(last, static_cast<std::size_t>(m.position(0)) - last);
    named += "name" + m[1].str() + prefix + m[2].str() + "\"";
    last = static_cast<std::size_t>(m.position(0) + m.length(0));
  }
  named += text.substr(last);
  std::string out;
  last = 0;
  for (auto it = std::sregex_iterator(named.begin(), named.end(), ref_attr); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    out += named.substr(last, static_cast<std::size_t>(m.position(0)) - last);
    const bool own = defined.count(m[3].str()) != 0;
    out += m[1].str() + m[2].str() + (own ? prefix : "") + m[3].str() + "\"";
    last = static_cast<std::size_t>(m.position(0) + m.length(0));
  }
  out += named.substr(last);
  return out;
}

std::string mjcf_error_line(const std::string& mujoco_message, const std::string& path, const std::string& prefix) {
  std::string what = mujoco_message;
  for (std::size_t at = 0; !prefix.empty() && (at = what.find(prefix, at)) != std::string::npos;) what.erase(at, prefix.size());
  for (const char* noise : {"MuJoCo error: ", "Error: "}) {
    if (const std::size_t at = what.find(noise); at != std::string::npos) what.erase(at, std::string(noise).size());
  }
  // One line: MuJoCo puts the element and its position on a second line.
  for (char& c : what) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!what.empty() && what.back() == ' ') what.pop_back();
  static const std::regex line_re(R"re(\bline(?: number)?\s*=?\s*(\d+))re", std::regex::icase);
  static const std::regex column_re(R"re(\bcolumn\s*=?\s*(\d+))re", std::regex::icase);
  std::smatch line, column;
  if (!std::regex_search(what, line, line_re)) return path + ": " + what;
  std::string where = path;
  where.append(":").append(line[1].str());
  if (std::regex_search(what, column, column_re)) where.append(":").append(column[1].str());
  return where.append(": ").append(what);
}

} // namespace sreh
