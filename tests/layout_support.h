// Helpers the layout tests share: floors laid from a field, and layout.svg read back.
#pragma once

#include <expat.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include "curdle/curdling.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "export/drawing/layout_png.h"
#include "export/drawing/svg.h"
#include "kinds/park.h"
#include "kinds/perforation.h"
#include "kinds/rhythm.h"
#include "layout/builder.h"
#include "layout/piece.h"
#include "layout/zone.h"
#include "test_support.h"

namespace curdle {

using test::design;

namespace test {
// 100 mm tiles of four values, 2 and 3 laid in one product (the same name and colour).
inline LayoutSpec two_values_one_product() {
  LayoutSpec spec = layout_spec();
  spec.module_w = spec.module_h = 100;
  spec.value_colours = {Rgb{230, 230, 220}, Rgb{140, 140, 130}, Rgb{60, 60, 60}, Rgb{60, 60, 60}};
  spec.materials = {"Buff", "Grey", "Black", "Black"};
  return spec;
}

// The paper's park (fig. 5): trees, benches and grey paving on 3 x 3 m cells, 300 mm clear.
inline LayoutSpec trees_and_benches(const std::string& tree = "tree") {
  LayoutSpec spec = layout_spec();
  spec.set_kind(layout_kind("park"));
  spec.module_w = spec.module_h = 3000;
  spec.own<ParkKeys>().clearance = 300;
  spec.own<ParkKeys>().elements = {{tree, false, true, 1000, 1000, Rgb{58, 138, 79}},
                                   {"bench", false, false, 1000, 450, Rgb{138, 90, 43}},
                                   {"grey paving", true, false, 0, 0, Rgb{154, 154, 154}}};
  return spec;
}
}  // namespace test

// The floor or wall of `spec` laid from a field of exactly its elements, curdled with `seed`.
inline Layout lay_floor(const Design& d, const LayoutSpec& spec, uint64_t seed) {
  Design sized = d;
  const auto cells = elements_to_cover(spec);
  sized.field.size = {cells[0], cells[1], 1};
  return make_layout(sized, curdle(sized, seed, sized.field), sized.field, spec);
}

inline double intersection(const Rect& a, const Rect& b) {
  const double w = std::min(a.right(), b.right()) - std::max(a.x, b.x);
  const double h = std::min(a.top(), b.top()) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0;
}

struct SvgSummary {
  std::map<int, uint64_t> counts;  // value -> elements, from data-count
  std::set<std::string> ids;
  std::set<std::string> classes;
  std::string width, height, view_box;
  int patterns = 0, pattern_parts = 0;
  std::map<int, std::string> fills;
};

inline SvgSummary parse_svg(const std::string& text) {
  SvgSummary s;
  struct State {
    SvgSummary* s;
    int value = -1;
    int depth = 0, value_depth = -1;
  } state{&s};
  XML_Parser p = XML_ParserCreate("UTF-8");
  XML_SetUserData(p, &state);
  XML_SetElementHandler(
      p,
      [](void* data, const XML_Char* name, const XML_Char** attrs) {
        auto* st = static_cast<State*>(data);
        ++st->depth;
        std::map<std::string, std::string> a;
        for (int i = 0; attrs[i]; i += 2) a[attrs[i]] = attrs[i + 1];
        const std::string tag = name;
        if (tag == "svg")
          st->s->width = a["width"], st->s->height = a["height"], st->s->view_box = a["viewBox"];
        if (a.count("id")) {
          EXPECT_TRUE(st->s->ids.insert(a["id"]).second) << "duplicate id " << a["id"];
        }
        if (a.count("class")) st->s->classes.insert(a["class"]);
        if (tag == "pattern") ++st->s->patterns;
        if (tag == "rect" && st->depth == 4 && st->s->patterns > 0 && st->value < 0)
          ++st->s->pattern_parts;
        if (tag == "g" && a["class"] == "value") {
          st->value = std::stoi(a["data-value"]);
          st->value_depth = st->depth;
          st->s->fills[st->value] = a["fill"];
        } else if (st->value >= 0 && a.count("data-count")) {
          st->s->counts[st->value] += std::stoull(a["data-count"]);
        }
      },
      [](void* data, const XML_Char*) {
        auto* st = static_cast<State*>(data);
        if (st->depth == st->value_depth) st->value = -1, st->value_depth = -1;
        --st->depth;
      });
  EXPECT_EQ(XML_Parse(p, text.data(), static_cast<int>(text.size()), 1), XML_STATUS_OK)
      << XML_ErrorString(XML_GetErrorCode(p)) << " at line " << XML_GetCurrentLineNumber(p);
  XML_ParserFree(p);
  return s;
}

inline std::string svg_of(const Layout& built) {
  Layout layout = built;
  layout.source.description = "a <test> & more";  // the title block escapes it
  layout.source.seed = 1;
  std::ostringstream out;
  write_layout_svg(out, layout);
  return out.str();
}

}  // namespace curdle
