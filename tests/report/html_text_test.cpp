// Text from a run dir never becomes markup or closes a script element.

#include "motoflex/report/html_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace motoflex::report {
namespace {

TEST(EscapeHtml, EscapesTheFiveMarkupCharacters) {
  EXPECT_EQ(escape_html("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(escape_html("LHipRoll 0.5 deg"), "LHipRoll 0.5 deg");
  EXPECT_EQ(escape_html("<script>alert(1)</script>"), "&lt;script&gt;alert(1)&lt;/script&gt;");
  EXPECT_EQ(escape_html(""), "");
}

TEST(JsonForScript, NoStringCanCloseTheScriptAndTheJsonStillParses) {
  nlohmann::json value;
  value["name"] = "evil</script><script>alert(1)</script><!--";
  value["sep"] = "a\u2028b\u2029c";
  value["nan"] = std::numeric_limits<double>::quiet_NaN();
  value["inf"] = std::numeric_limits<double>::infinity();
  value["x"] = {1.5, -2.0};
  const std::string text = json_for_script(value);
  EXPECT_EQ(text.find('<'), std::string::npos) << text;
  EXPECT_EQ(text.find("\xE2\x80\xA8"), std::string::npos);
  EXPECT_EQ(text.find("\xE2\x80\xA9"), std::string::npos);
  const nlohmann::json back = nlohmann::json::parse(text);
  EXPECT_EQ(back["name"], value["name"]);
  EXPECT_EQ(back["sep"], value["sep"]);
  EXPECT_TRUE(back["nan"].is_null());
  EXPECT_TRUE(back["inf"].is_null());
  EXPECT_EQ(back["x"][0], 1.5);
}

TEST(JsonForScript, BrokenUtf8IsReplacedNotFatal) {
  const nlohmann::json value = std::string("log\xff\xfe");
  const std::string text = json_for_script(value);
  nlohmann::json back;
  EXPECT_NO_THROW(back = nlohmann::json::parse(text));
  EXPECT_TRUE(back.is_string());
}

TEST(FormatNumber, SignificantDigitsAndSpecialValues) {
  EXPECT_EQ(format_number(3.14159265, 3), "3.14");
  EXPECT_EQ(format_number(1.5e-7), "1.5e-07");
  EXPECT_EQ(format_number(std::nan("")), "n/a");
  EXPECT_EQ(format_number(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(format_number(std::numeric_limits<double>::infinity()), "inf");
}

}  // namespace
}  // namespace motoflex::report
