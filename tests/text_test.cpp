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

TEST(Text, NamesThatWouldNotShowAsTheyReadAreUnsafe) {
  EXPECT_EQ(unsafe_text("Grès cérame, Ølstykke 3"), "");
  EXPECT_EQ(unsafe_text("ABC xyz ~!"), "");  // every printable ASCII letter is safe
  EXPECT_EQ(unsafe_text("a\nb"), "a line break or tab");
  EXPECT_EQ(unsafe_text("a\x01"), "a control character");
  EXPECT_EQ(unsafe_text("\xc3"), "bytes that are not UTF-8");
  EXPECT_NE(unsafe_text("brick\u202Egpj.exe").find("bidirectional control (U+202E)"),
            std::string::npos);
  EXPECT_NE(unsafe_text("zero\u200Bwidth").find("invisible character (U+200B)"), std::string::npos);
  EXPECT_NE(unsafe_text("end\xEF\xBF\xBF").find("non-character (U+FFFF)"), std::string::npos);
  // XML forbids U+FFFE and U+FFFF: the escaper drops them as it drops control characters.
  EXPECT_EQ(xml_escape("a\xEF\xBF\xBF"
                       "b\xEF\xBF\xBE"),
            "ab");
}

}  // namespace
TEST(Text, ForeignNamesAreShownWithTheirControlsEscaped) {
  EXPECT_EQ(shown_name("A-OTLN"), "A-OTLN");
  EXPECT_EQ(shown_name("Gr\xC3\xA8s"), "Gr\xC3\xA8s");      // letters as they are
  EXPECT_EQ(shown_name("X\x1b[2J\x07"), "X\\x1B[2J\\x07");  // a terminal's escape
  EXPECT_EQ(shown_name("a\xE2\x80\xAE"
                       "b"),
            "a\\u202Eb");                         // right-to-left override
  EXPECT_EQ(shown_name("\xC2\x9B"), "\\u009B");   // C1's CSI
  EXPECT_EQ(shown_name("\xFF"), "\xEF\xBF\xBD");  // not UTF-8
}

}  // namespace curdle
