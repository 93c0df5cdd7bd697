#pragma once

// The files the HTML report inlines so that it works offline: plotly.js (vendored from npm in
// third_party/plotly/, MIT licence) and the report page's own script and style sheet
// (src/report/report_page.js, report_page.css). They are built into the binary, so the report
// needs no data directory, in the build tree or installed.

#include <string_view>

namespace motoflex::report {

std::string_view plotly_js();       // plotly.js cartesian bundle, minified, with its licence
std::string_view plotly_version();  // e.g. "4.1.1"
std::string_view report_page_js();  // draws the figures from the page's JSON data
std::string_view report_page_css();

}  // namespace motoflex::report
