#include "io/html_page.hpp"

namespace sreh::io {

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string html_page_open(std::string_view title, std::string_view head) {
  std::string o = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>";
  o += html_escape(title);
  o += "</title>\n";
  o += head;
  o += "</head>\n<body>\n";
  return o;
}

std::string html_page_close() { return "</body>\n</html>\n"; }

std::string html_page(std::string_view title, std::string_view head, std::string_view body) {
  std::string o = html_page_open(title, head);
  o += body;
  o += html_page_close();
  return o;
}

} // namespace sreh::io
