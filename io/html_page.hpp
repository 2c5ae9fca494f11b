// The one HTML page shell (issue 13): doctype, language, charset, title,
// whatever the page puts in its <head>, then its body. Used by the run
// report (renders/report.cpp), the sizing reports (sizing/report.cpp) and
// serve's live page (serve/http_server.cpp). It lives in io/, the lowest
// layer, because serve sits on scenarios and must not depend on renders
// (an optional folder: SREH_WITH_RENDER=OFF builds serve without it);
// what a page looks like (CSS, scripts) stays with the page.
#pragma once
#include <string>
#include <string_view>

namespace sreh::io {

// What html_escape does with control characters and bytes outside ASCII:
// keep them (UTF-8 pages) or write each byte as a character reference
// (`&#xNN;`, for the IODD-like export, an ASCII document).
enum class NonAscii { Keep, AsReference };

// Text for HTML/XML content and attribute values: & < > " ' escaped. The
// one escaper of the project (HTML pages, SVG plots, the IODD export).
std::string html_escape(std::string_view text, NonAscii non_ascii = NonAscii::Keep);

// The style of every page (CSS, no <style> tag): the reports put it into
// their <head> (renders/figure.hpp page_head), serve's live page too, under
// its own app.css (issue 39: one look).
extern const char* const kPageCss;

// The print stylesheet every page carries (A4, no plot or table cut by a
// page break), after the page's own <head> content.
extern const char* const kPrintCss;

// "<!DOCTYPE html>...<title>TITLE</title>\n" + head + kPrintCss +
// "</head>\n<body>\n".
// `title` is plain text (escaped here); `head` is markup (<style>, <link>,
// <script>), each element ending its own line.
std::string html_page_open(std::string_view title, std::string_view head);
// "</body>\n</html>\n".
std::string html_page_close();
// The whole page: open + body + close.
std::string html_page(std::string_view title, std::string_view head, std::string_view body);

} // namespace sreh::io
