// What the page shows of a run, as JSON: the recipe described (design, layout facts, legend,
// the surface drawn over the floor, the downloads), a segment curdled with its report and
// values, a picture studied, and the blend of curd colours. The server only passes it on.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "app/picture_study.h"
#include "app/run.h"

namespace curdle::app {

// The files the page may download: the registry's single-file outputs (those of a layout only
// when there is one, those of a kind only for it; `kind` empty: every kind's), and recipe.toml.
// `site_drawing`: the layout lies in a DXF it was read from (layout-site.dxf is offered).
std::vector<std::string> page_downloads(bool with_layout, std::string_view kind = {},
                                        bool site_drawing = true);

// ResourceLimitError when `view` generates more than `limit` cells; `what` opens the message
// ("this request would generate").
void check_cells(const Design& design, const Box& view, uint64_t limit, const char* what);

// The run as the page draws and edits it: name, lattice, curds and their colours, field,
// default window, layout facts (element, cell size, the surface and where the segment's cells
// lie), legend and downloads.
nlohmann::ordered_json describe_run(const Run& run);

// The run curdled over `view`: describe_run, then the view, the report and (on 1-D and 2-D
// lattices, when asked) each cell's value, base64 bytes in rows from the view's corner.
nlohmann::ordered_json segment_json(const Run& run, const Box& view, bool with_values);

// The curd over `view` as the page draws it: segment_json's head without the values (with
// "value_bits", 0 on a 3-D lattice) and the values packed as pack_values packs them
// (curdle/packed_values.h), row by row from the view's corner, x fastest.
struct PageField {
  nlohmann::ordered_json head;
  std::string values;
};
PageField page_field(const Run& run, const Box& view);

// A picture measured and fitted: measure.json's content, and the fitted recipe's lattice,
// curds, stages and text.
nlohmann::ordered_json picture_study_json(const PictureStudy& study);

// The colour of every value as the library blends the curds' colours ("#rrggbb", one per
// curd, at most 8), value 0 first; InputError naming `colour`.
nlohmann::ordered_json value_colours_json(const std::vector<std::string>& curd_colours);

}  // namespace curdle::app
