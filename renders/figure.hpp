// One plot in an HTML report (issue 16): the static SVG (print, no scripts)
// and, for time series, a zoomable, pannable dygraph drawn from the same
// data with Debian's libjs-dygraphs inlined into the page (offline). Used by
// the run report and the sizing reports alike.
#pragma once
#include <string>

#include "renders/svg_plot.hpp"

namespace sreh::report {

// <style> and <script> for the page's <head>: dygraphs and the small helper
// that draws a figure. Once per page, before any figure.
std::string interactive_head();

// The <head> content of every report page: io::kPageCss and interactive_head(),
// for io::html_page / io::html_page_open (the one page shell).
std::string page_head();

// The figure: SVG always; with `interactive` and series that share one x
// vector also a dygraph, which replaces the SVG on screen once it is drawn.
std::string figure(const svg::Plot& plot, bool interactive = true);

} // namespace sreh::report
