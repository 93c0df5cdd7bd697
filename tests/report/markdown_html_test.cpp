// The markdown motoflex writes (residuals.md, a loop's report.md) rendered into the report.

#include "motoflex/report/markdown_html.hpp"

#include <gtest/gtest.h>

#include "report_test_support.hpp"

namespace motoflex::report {
namespace {

TEST(Base64, Rfc4648TestVectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(MarkdownToHtml, HeadingsTablesParagraphsAndEscaping) {
  const std::string md =
      "# Residuals of nao <quick>\n\nTraining logs: overall RMS `0.41` deg,\n**bold** text.\n\n"
      "| joint | RMS before (deg) |\n|---|---|\n| LHipRoll | 0.1 |\n| R<Knee> | 0.2 |\n"
      "after the table\n";
  const std::string html = markdown_to_html(md, "/nonexistent", 1);
  EXPECT_NE(html.find("<h2>Residuals of nao &lt;quick&gt;</h2>"), std::string::npos) << html;
  EXPECT_NE(html.find("<p>Training logs: overall RMS <code>0.41</code> deg, <strong>bold</strong> "
                      "text.</p>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<th>joint</th><th>RMS before (deg)</th>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>LHipRoll</td><td>0.1</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>R&lt;Knee&gt;</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<p>after the table</p>"), std::string::npos) << html;
  EXPECT_EQ(html.find("<quick>"), std::string::npos);
}

TEST(MarkdownToHtml, ImagesAreInlinedWhenTheyAreThereAndNotedOtherwise) {
  const auto dir = motoflex::testing::fresh_dir("report_markdown_images");
  // The smallest PNG signature plus a little payload is enough for the data: URI.
  motoflex::testing::write_text(dir / "plot.png", std::string("\x89PNG\r\n\x1a\nabc", 11));
  motoflex::testing::write_text(dir / "fake.png", "not a png at all");
  const std::string html = markdown_to_html(
      "![before and after](plot.png)\n\n![fake](fake.png)\n\n![gone](gone.png)\n", dir.string());
  EXPECT_NE(html.find("<img src=\"data:image/png;base64,iVBORw0KGgphYmM=\" alt=\"before and "
                      "after\">"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("image fake.png: not available"), std::string::npos) << html;
  EXPECT_NE(html.find("image gone.png: not available"), std::string::npos) << html;
  EXPECT_EQ(png_data_uri((dir / "plot.png").string(), 5), "");  // over the size limit
}

}  // namespace
}  // namespace motoflex::report
