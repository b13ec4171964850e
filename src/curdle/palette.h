// Colours of the overlay's values for previews: each curd has a colour, and a cell where
// several curds survive takes their mean (the paper's a + b = c: red and blue give purple).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

// The curd's own colour, or one from a default set of distinct, print-safe colours.
Rgb curd_colour(const std::vector<CurdSpec>& curds, size_t curd);

struct CurdGroup;  // markov.h

// A state's colour: a plain curd's own, or a Markov curd's state's (state >= 1).
Rgb state_colour(const std::vector<CurdSpec>& curds, const CurdGroup& group, uint32_t state);

// The colours of what a value holds: one per curd present, in curd order (a Markov curd's by
// its state). Empty for value 0.
std::vector<Rgb> value_parts(const std::vector<CurdSpec>& curds, uint32_t value);

// One colour per value (2^n entries); value 0, where no curd survived, is a light paving grey.
std::vector<Rgb> value_colours(const std::vector<CurdSpec>& curds);

// "#rrggbb", as recipes, SVG and CSV write colours.
std::string hex_colour(const Rgb& colour);
// "#rrggbb", or nothing when the text is not one.
std::optional<Rgb> parse_hex_colour(std::string_view text);

inline constexpr Rgb kEmptyColour{236, 232, 222};

}  // namespace curdle
