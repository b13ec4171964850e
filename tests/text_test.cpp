// Tests of text.h: UTF-8 checked, control characters found, XML escaped and its forbidden
// characters dropped.
#include "curdle/text.h"

#include <gtest/gtest.h>

namespace curdle {
namespace {

TEST(Text, Utf8ControlCharactersAndXmlEscaping) {
  EXPECT_TRUE(valid_utf8("Grès cérame"));
  EXPECT_FALSE(valid_utf8("\xc3"));          // cut short
  EXPECT_FALSE(valid_utf8("\xc0\xaf"));      // overlong
  EXPECT_FALSE(valid_utf8("\xed\xa0\x80"));  // a surrogate
  EXPECT_TRUE(
      has_control_characters("a\x01"
                             "b"));
  EXPECT_TRUE(has_control_characters("a\x7f"));
  EXPECT_FALSE(has_control_characters("a\tb\r\n"));  // tab and line ends are text
  EXPECT_FALSE(has_control_characters("Grès"));
  EXPECT_EQ(xml_escape("<a href=\"x\">&'</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(xml_escape(std::string("a\x01"
                                   "b")),
            "ab");  // XML 1.0 forbids it
}

}  // namespace
}  // namespace curdle
