// The inlined assets are in the binary, whole, and safe to put inside <script>/<style>.

#include "motoflex/report/page_assets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>

namespace motoflex::report {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string source_file(const std::string& path) {
  std::ifstream in(std::string(MOTOFLEX_SOURCE_DIR) + "/" + path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(PageAssets, ThePlotlyBundleIsEmbeddedWholeWithItsBanner) {
  const std::string_view js = plotly_js();
  EXPECT_EQ(js, source_file("third_party/plotly/plotly-cartesian.min.js"));
  EXPECT_GT(js.size(), 1000000u);
  EXPECT_NE(
      js.substr(0, 300).find("plotly.js (cartesian - minified) v" + std::string(plotly_version())),
      std::string_view::npos);
  EXPECT_NE(js.substr(0, 300).find("MIT"), std::string_view::npos);
  EXPECT_EQ(js.data()[js.size()], '\0');  // the terminating byte after the asset
}

TEST(PageAssets, ThePagesOwnScriptAndStyleAreEmbeddedAsInTheSourceTree) {
  EXPECT_EQ(report_page_js(), source_file("src/report/report_page.js"));
  EXPECT_EQ(report_page_css(), source_file("src/report/report_page.css"));
}

TEST(PageAssets, NoAssetCanEndItsScriptOrStyleElementEarly) {
  EXPECT_EQ(lower(plotly_js()).find("</script"), std::string::npos);
  EXPECT_EQ(lower(report_page_js()).find("</script"), std::string::npos);
  EXPECT_EQ(lower(report_page_css()).find("</style"), std::string::npos);
}

}  // namespace
}  // namespace motoflex::report
