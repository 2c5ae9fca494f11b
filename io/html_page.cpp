#include "io/html_page.hpp"

namespace sreh::io {

// The look of every page (issue 39: reports and serve's live page alike):
// type, headings, tables, verdict colours, figures.
const char* const kPageCss = R"css(
body{font-family:system-ui,-apple-system,"Segoe UI",sans-serif;margin:24px auto;max-width:1240px;color:#222;padding:0 16px}
h1{font-size:22px;margin-bottom:4px;overflow-wrap:anywhere}h2{font-size:17px;margin-top:28px;border-bottom:1px solid #ddd;padding-bottom:4px}
.result{display:inline-block;padding:3px 12px;border-radius:4px;font-weight:bold;color:#fff}
.pass,.ok{background:#2e7d32}.fail,.bad{background:#c62828}
table{border-collapse:collapse;font-size:13px;display:block;overflow-x:auto;max-width:100%}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}
th{background:#f2f2f2}td.l,th.l{text-align:left}td.okc{color:#2e7d32;font-weight:bold}td.badc{color:#c62828;font-weight:bold}
svg.plot{display:block;margin:10px 0;width:100%;height:auto}video,img.video{max-width:100%;height:auto;background:#000}
pre,code.cmd{background:#f7f7f7;padding:6px 8px;font-size:13px;overflow-x:auto;display:block;white-space:pre-wrap;overflow-wrap:anywhere}
p,li{overflow-wrap:anywhere}
.note{color:#666;font-size:12px}ul.failed li{color:#c62828;margin:3px 0}
.fig{margin:12px 0}.fig .dy{display:none;width:100%;height:340px}
.fig .dytitle,.fig .dylegend,.fig .dykey{display:none;font-size:13px}.fig .dytitle{font-weight:bold;font-size:14px;margin:4px 0}
.fig .dylegend{min-height:1.3em}.fig .dykey span.k{margin-right:14px;white-space:nowrap}
.fig .dykey i{display:inline-block;width:18px;vertical-align:middle;margin-right:4px}
.fig.live .dy,.fig.live .dytitle,.fig.live .dylegend,.fig.live .dykey{display:block}.fig.live .static{display:none}
.fig .hint{display:none;color:#666;font-size:11px}.fig.live .hint{display:block}
.verdict{border:1px solid #ccc;border-radius:6px;padding:8px 14px;margin:12px 0;break-inside:avoid}
.verdict table.bars{display:table;width:100%;border:none}.verdict table.bars td{border:none;padding:2px 8px;vertical-align:middle}
.verdict td.bar{width:45%}.verdict .track{height:14px}.verdict table.bars td:first-child,.verdict table.bars td:nth-child(3){white-space:nowrap}.verdict dl{display:grid;grid-template-columns:max-content 1fr;gap:2px 14px;margin:8px 0;font-size:13px}
.verdict dt{color:#555}.verdict dd{margin:0}
table.verdicts td.mini{min-width:150px;white-space:nowrap}table.verdicts .track{display:inline-block;width:90px;height:10px;margin-right:6px;vertical-align:middle}
.verdict .track,table.verdicts .track{position:relative;background:#eee;border-radius:3px}
.verdict .fill,table.verdicts .fill{position:absolute;left:0;top:0;bottom:0;border-radius:3px}
.fill.okb{background:#43a047}.fill.warnb{background:#f9a825}.fill.badb{background:#e53935}
.verdict .mark,table.verdicts .mark{position:absolute;top:-3px;bottom:-3px;width:2px;background:#222}.mark.req{background:#7b1fa2!important}
@media print{.fig.live .dy,.fig.live .hint,.fig.live .dytitle,.fig.live .dylegend,.fig.live .dykey{display:none}.fig.live .static{display:block}}
)css";

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
    // Issue 37: the sweep's verdict table fits the paper's 186 mm (it was cut after "thermal"): shorter bars.
    "table.verdicts td.mini{min-width:0}table.verdicts .track{width:40px}table.verdicts td,table.verdicts th{padding:3px 4px}\n"
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
