#pragma once

// The markdown that motoflex itself writes (residuals.md of `motoflex residuals`, report.md of
// `motoflex loop`) shown inside the HTML report. Only what those files use is understood:
// headings (#, ##, ###), pipe tables, paragraphs, `code`, **bold** and images ![alt](file.png).
// Everything else is shown as text, escaped.

#include <string>
#include <string_view>

namespace motoflex::report {

// HTML for `markdown`. Headings are shifted down by `heading_offset` levels (a report section
// already has its own heading). An image whose file (relative to `image_dir`) exists and is a
// PNG of at most 2 MB is inlined as a data: URI so that the report stays one file; any other
// image becomes a note naming the file.
std::string markdown_to_html(std::string_view markdown, const std::string& image_dir,
                             int heading_offset = 1);

// data:image/png;base64,... for a PNG file; empty when the file is missing, not a PNG or larger
// than `max_bytes`.
std::string png_data_uri(const std::string& path, std::size_t max_bytes = 2u << 20);

// Base64 (RFC 4648, with padding) of `bytes`.
std::string base64(std::string_view bytes);

}  // namespace motoflex::report
