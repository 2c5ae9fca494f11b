#include "io/provenance.hpp"

#include <cstdlib>
#include <ctime>

#include "io/html_page.hpp"

namespace sreh::io {
namespace {

Provenance& origin() {
  static Provenance o{"sreh-twin library", "(library)", {}};
  return o;
}

} // namespace

void set_report_origin(const std::string& made_by, const std::string& version) {
  origin().made_by = made_by;
  origin().version = version;
}

Provenance report_provenance(std::vector<std::pair<std::string, std::string>> inputs) {
  Provenance p = origin();
  p.inputs = std::move(inputs);
  return p;
}

std::string report_date() {
  std::time_t t = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr && *epoch != '\0') {
    char* end = nullptr;
    const long long v = std::strtoll(epoch, &end, 10);
    if (end != nullptr && *end == '\0' && v >= 0) t = static_cast<std::time_t>(v);
  }
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

std::string provenance_html(const Provenance& p) {
  std::string o = "<section class=\"provenance\" id=\"provenance\">\n<table>\n";
  auto row = [&o](const std::string& name, const std::string& value) {
    o += "<tr><th class=\"l\">" + html_escape(name) + "</th><td class=\"l\">" + html_escape(value) + "</td></tr>\n";
  };
  row("made by", p.made_by);
  row("version", "sreh-twin " + p.version);
  row("date", report_date());
  for (const auto& [name, value] : p.inputs) row(name, value);
  return o + "</table>\n</section>\n";
}

std::string with_provenance(const std::string& page, const Provenance& p) {
  std::string out = page;
  std::size_t at = out.find("</h1>");
  if (at != std::string::npos) at += 5;
  else if ((at = out.find("<body>")) != std::string::npos) at += 6;
  else at = 0;
  if (at < out.size() && out[at] == '\n') ++at;
  out.insert(at, provenance_html(p));
  return out;
}

} // namespace sreh::io
