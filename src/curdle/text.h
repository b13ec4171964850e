// Text from users: recipe names and descriptions, query strings. Checked once where it enters,
// and escaped once where it leaves as markup.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace curdle {

// Well-formed UTF-8 (no overlong forms, surrogates or code points above U+10FFFF).
bool valid_utf8(std::string_view text);

// True when the text holds a control character other than tab, line feed and carriage return
// (XML 1.0 forbids them; terminals and CSV readers misread them).
bool has_control_characters(std::string_view text);

// Text for XML character data and attribute values: &, <, >, " and ' escaped, and characters
// XML forbids (controls, invalid UTF-8) dropped.
std::string xml_escape(std::string_view text);

// The code point of the character at text[i], moving i past it; a byte that does not begin
// well-formed UTF-8 is U+FFFD and moves i by one.
uint32_t next_code_point(std::string_view text, size_t& i);

// Appends the code point (below U+10000) to `out` as UTF-8.
void append_utf8(std::string& out, uint32_t code_point);

// What makes `text` unsafe as a name that files and drawings show (a recipe's, a material's, a
// zone's), or empty when nothing does: bytes that are not UTF-8, control characters, line
// breaks and tabs, bidirectional controls (which reorder what a reader sees), invisible
// characters (zero-width spaces and joiners) and non-characters (U+FFFF).
std::string unsafe_text(std::string_view text);

// A name read from someone else's file (a drawing's layer, a model's node) as it may be shown
// in a terminal, a message or a drawing: control characters (C0, DEL, C1), bidirectional
// controls and invisible characters written as \x1B or \u202E, bytes that are not UTF-8 as
// U+FFFD; everything else as it is.
std::string shown_name(std::string_view text);

}  // namespace curdle
