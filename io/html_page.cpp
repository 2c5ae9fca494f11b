#include "io/html_page.hpp"

namespace sreh::io {

// Every page prints as a clean A4 PDF from a browser (issue 29): each plot,
// table and verdict is one block that a page break never cuts, headings stay
// with what follows, plots fit the paper's width.
const char* const kPrintCss =
    "<style media=\"print\">\n"
    "@page{size:A4;margin:12mm}\n"
    "body{max-width:none;margin:0;padding:0}\n"
    ".fig,svg,table,pre,.verdict,.port,figure,img,tr{break-inside:avoid;page-break-inside:avoid}\n"
    "h1,h2,h3{break-after:avoid;page-break-after:avoid}\n"
    "svg,img,canvas{max-width:100%!important;height:auto}\n"
    "button,input,video,.hint{display:none!important}\n"
    "</style>\n";

std::string html_escape(std::string_view text, NonAscii non_ascii) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (non_ascii == NonAscii::AsReference && (byte < 0x20 || byte >= 0x7F)) {
      out += "&#x";
      if (byte >= 0x10) out += kHex[byte >> 4];
      out += kHex[byte & 0xF];
      out += ';';
      continue;
    }
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
  o += kPrintCss;
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
