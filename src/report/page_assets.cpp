#include "motoflex/report/page_assets.hpp"

// The assets are assembled into read-only data with `.incbin`: a 1.5 MB file as a C++ string or
// array initialiser would exceed ISO C++'s 65536-character literal limit (-Woverlength-strings)
// or cost seconds and hundreds of MB in the compiler. MOTOFLEX_REPORT_PLOTLY_JS and friends are
// absolute paths set for this file only (src/report/CMakeLists.txt, which also makes this object
// depend on the files). ccache does not cache a file that uses .incbin, so a changed asset is
// always picked up. Each asset is followed by a NUL byte so that it can be viewed as a C string.

#define MOTOFLEX_INCBIN(symbol, file)  \
  asm(".pushsection .rodata\n"         \
      ".global " #symbol               \
      "_begin\n"                       \
      ".global " #symbol               \
      "_end\n"                         \
      ".balign 16\n" #symbol           \
      "_begin:\n"                      \
      ".incbin \"" file "\"\n" #symbol \
      "_end:\n"                        \
      ".byte 0\n"                      \
      ".popsection\n")

MOTOFLEX_INCBIN(motoflex_report_plotly_js, MOTOFLEX_REPORT_PLOTLY_JS);
MOTOFLEX_INCBIN(motoflex_report_page_js, MOTOFLEX_REPORT_PAGE_JS);
MOTOFLEX_INCBIN(motoflex_report_page_css, MOTOFLEX_REPORT_PAGE_CSS);

extern "C" {
extern const char motoflex_report_plotly_js_begin[];
extern const char motoflex_report_plotly_js_end[];
extern const char motoflex_report_page_js_begin[];
extern const char motoflex_report_page_js_end[];
extern const char motoflex_report_page_css_begin[];
extern const char motoflex_report_page_css_end[];
}

namespace motoflex::report {

std::string_view plotly_js() {
  return {
      motoflex_report_plotly_js_begin,
      static_cast<std::size_t>(motoflex_report_plotly_js_end - motoflex_report_plotly_js_begin)};
}

std::string_view plotly_version() {
  return MOTOFLEX_REPORT_PLOTLY_VERSION;
}

std::string_view report_page_js() {
  return {motoflex_report_page_js_begin,
          static_cast<std::size_t>(motoflex_report_page_js_end - motoflex_report_page_js_begin)};
}

std::string_view report_page_css() {
  return {motoflex_report_page_css_begin,
          static_cast<std::size_t>(motoflex_report_page_css_end - motoflex_report_page_css_begin)};
}

}  // namespace motoflex::report
