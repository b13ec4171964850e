#include "app/page.h"

#include "app/outputs.h"
#include "building/building.h"
#include "building/coursing.h"
#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "curdle/packed_values.h"
#include "curdle/palette.h"
#include "curdle/report.h"
#include "export/report/measure_files.h"
#include "export/report/report_json.h"
#include "kinds/registry.h"
#include "layout/builder.h"
#include "layout/cell_placement.h"
#include "layout/legend.h"

using nlohmann::ordered_json;

namespace curdle::app {
namespace {

std::string base64(const uint8_t* data, size_t size) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (size_t i = 0; i < size; i += 3) {
    const uint32_t n = uint32_t{data[i]} << 16 | (i + 1 < size ? uint32_t{data[i + 1]} << 8 : 0) |
                       (i + 2 < size ? data[i + 2] : 0);
    out += kAlphabet[n >> 18 & 63];
    out += kAlphabet[n >> 12 & 63];
    out += i + 1 < size ? kAlphabet[n >> 6 & 63] : '=';
    out += i + 2 < size ? kAlphabet[n & 63] : '=';
  }
  return out;
}

ordered_json box_json(const Box& b, int dimension) {
  ordered_json j = ordered_json::array();
  for (int d = 0; d < dimension; ++d) j.push_back(b.origin[d]);
  for (int d = 0; d < dimension; ++d) j.push_back(b.size[d]);
  return j;
}

ordered_json polygon_json(const Polygon& polygon) {
  ordered_json points = ordered_json::array();
  for (const auto& p : polygon) points.push_back({p[0], p[1]});
  return points;
}

// The surface the page draws over the floor's segment: its outline and zones in mm, and where
// the segment's cells lie (mm = origin_mm + cell_mm * u, u in cells from the segment's corner,
// without a bond's course shifts; round a building's ring u is taken round period_mm).
ordered_json surface_json(const LayoutSpec& spec) {
  const auto need = elements_to_cover(spec);
  Box segment;
  segment.size = {need[0], need[1], 1};
  const CellPlacement placement = cell_placement(spec, segment);
  const auto extent = surface_extent(spec, segment);
  ordered_json zones = ordered_json::array();
  for (const Zone& z : spec.zones) {
    ordered_json zone = {{"name", z.name},
                         {"rule", z.rule == ZoneRule::exclude ? "exclude" : "value"},
                         {"polygon", polygon_json(z.polygon)}};
    if (z.rule == ZoneRule::value) zone["value"] = z.value;
    zones.push_back(zone);
  }
  return {
      {"origin_mm", {placement.origin[0], placement.origin[1]}},
      {"cell_mm", {placement.scale[0], placement.scale[1]}},
      {"period_mm", placement.period},  // round a building's ring: x taken round, mm; 0: none
      {"outline_mm",
       polygon_json(spec.outline.empty()
                        ? Polygon{{0, 0}, {extent[0], 0}, {extent[0], extent[1]}, {0, extent[1]}}
                        : spec.outline)},
      {"zones", zones}};
}

// A building's façades on its unrolled strip, for the page to mark its corners and name its
// faces over the curd; null for any other layout.
ordered_json building_json(const LayoutSpec& spec) {
  const Envelope* envelope = spec.kind->envelope(spec);
  if (!envelope) return nullptr;
  ordered_json facades = ordered_json::array();
  for (const SurfaceFrame& f : envelope->facades)
    facades.push_back({{"name", f.name},
                       {"start_mm", f.start},
                       {"length_mm", f.length},
                       {"corner", f.last_of_path ? "end" : corner_kind(f.turn_at_end)}});
  return {{"closed", envelope->closed}, {"facades", facades}};
}

// Whether the kind the page names writes an output only its kind writes.
bool owned_by(std::string_view kind, const std::string& output) {
  const LayoutKind* k = find_layout_kind(kind);
  return k && k->owns_output(output);
}

}  // namespace

std::vector<std::string> page_downloads(bool with_layout, std::string_view kind,
                                        bool site_drawing) {
  std::vector<std::string> names;
  std::string why;
  for (const Output& o : output_registry())
    if (o.download && (with_layout || !o.needs_layout) && (site_drawing || !o.for_site_drawing) &&
        (!o.kind_owned || kind.empty() || owned_by(kind, o.name)) &&
        (!o.installed || o.installed(&why)))
      names.push_back(o.name);
  names.push_back("recipe.toml");
  return names;
}

void check_cells(const Design& d, const Box& view, uint64_t limit, const char* what) {
  const uint64_t cells = generation_box(d, view).cells();
  if (cells > limit)
    throw ResourceLimitError(std::string(what) + " " + std::to_string(cells) +
                             " cells; the server allows " + std::to_string(limit) +
                             ": choose a smaller field.cells or window, or start it with a larger "
                             "--max-cells");
}

ordered_json describe_run(const Run& s) {
  const Design& d = s.recipe.design;
  const int E = d.lattice.dimension;
  ordered_json j;
  j["name"] = d.name;
  j["description"] = s.recipe.design.description;
  j["recipe_path"] = s.recipe_path;
  j["lattice"] = {{"base", d.lattice.base},
                  {"dimension", E},
                  {"stages", d.lattice.stages},
                  {"mode", std::string(to_string(d.lattice.mode))}};
  j["curds"] = ordered_json::array();
  // One entry per [[curds]] table, so that the page's overrides name the recipe's own indices;
  // a Markov curd lists its states (its matrices are edited in the recipe).
  for (const CurdGroup& g : curd_groups(d.curds)) {
    const size_t c = g.first;
    if (g.chain) {
      ordered_json states = ordered_json::array();
      for (uint32_t st = 1; st <= g.chain->living(); ++st)
        states.push_back({{"name", g.chain->state_name(st)},
                          {"colour", hex_colour(state_colour(d.curds, g, st))}});
      j["curds"].push_back({{"name", d.curds[c].name},
                            {"markov", true},
                            {"states", states},
                            {"probabilities", ordered_json::array()},
                            {"colour", hex_colour(state_colour(d.curds, g, 1))}});
      continue;
    }
    ordered_json p = ordered_json::array();
    for (const Probability& q : d.curds[c].probabilities) p.push_back(q.text());
    j["curds"].push_back({{"name", d.curds[c].name},
                          {"probabilities", p},
                          {"colour", hex_colour(curd_colour(d.curds, c))}});
  }
  ordered_json field = ordered_json::array();
  for (int k = 0; k < E; ++k) field.push_back(d.field.size[k]);
  j["field"] = field;
  j["default_window"] = s.recipe.window ? box_json(*s.recipe.window, E) : ordered_json(nullptr);
  ordered_json legend = ordered_json::array();
  if (s.recipe.layout) {
    const LayoutSpec& spec = *s.recipe.layout;
    const auto entries = make_legend(d, spec);
    for (const LegendEntry& e : entries)
      legend.push_back({{"value", e.value}, {"label", e.label}, {"colour", hex_colour(e.colour)}});
    const bool line = spec.kind->dimension() == 1;
    j["layout"] = {
        {"element", std::string(spec.kind->element_noun())},
        {"cell_mm",
         {spec.module_w + spec.joint, line ? spec.module_h : spec.module_h + spec.joint}},
        {"has_value_colours", !spec.value_colours.empty()}};
    if (spec.size) {
      const auto need = elements_to_cover(spec);
      j["layout"]["size_mm"] = {(*spec.size)[0], (*spec.size)[1]};
      j["layout"]["segment_cells"] = {need[0], need[1]};
      if (spec.kind->dimension() == 2) j["layout"]["surface"] = surface_json(spec);
      if (const ordered_json b = building_json(spec); !b.is_null()) j["layout"]["building"] = b;
    }
  } else {
    const auto colours = value_colours(d.curds);
    for (uint32_t v = 0; v < colours.size(); ++v)
      legend.push_back(
          {{"value", v}, {"label", value_label(v, d.curds)}, {"colour", hex_colour(colours[v])}});
    j["layout"] = nullptr;
  }
  j["legend"] = legend;
  // What this recipe can download, from the registry: the page lists no names of its own.
  const std::vector<std::string> downloads = page_downloads(
      s.recipe.layout.has_value(), s.recipe.layout ? s.recipe.layout->kind->name() : "",
      s.recipe.layout && s.recipe.layout->site_frame);
  j["downloads"] = downloads;
  // What each is for, as the page's links say on hover ("... for QGIS").
  ordered_json about = ordered_json::object();
  for (const std::string& name : downloads)
    if (const Output* o = find_output(name)) about[name] = o->description;
  j["download_descriptions"] = about;
  return j;
}

namespace {

// The head both answers share: the run, the view and its report.
ordered_json segment_head(const Run& s, const Box& view, const CurdField& field) {
  const Design& d = s.recipe.design;
  const Report report = make_report(d, s.seed, field, view);
  ordered_json j = describe_run(s);
  j["seed"] = std::to_string(s.seed);
  j["view"] = box_json(view, d.lattice.dimension);
  j["report"] = report_to_json(report);
  return j;
}

// The view's values as bytes: one a cell up to eight curds, else two, little-endian.
std::string value_bytes(const Design& d, const CurdField& field, const Box& view, int& width) {
  width = d.curds.size() <= 8 ? 1 : 2;
  std::string bytes(view.cells() * static_cast<size_t>(width), '\0');
  char* out = bytes.data();
  scan_rows(field, view, [&](int64_t, int64_t, std::span<const uint16_t> row) {
    for (const uint16_t v : row) {
      *out++ = static_cast<char>(v & 0xff);
      if (width == 2) *out++ = static_cast<char>(v >> 8);
    }
  });
  return bytes;
}

}  // namespace

ordered_json segment_json(const Run& s, const Box& view, bool with_values) {
  const Design& d = s.recipe.design;
  const CurdField field = curdle(d, s.seed, view, s.generate);
  ordered_json j = segment_head(s, view, field);
  if (with_values && d.lattice.dimension <= 2) {
    int width = 1;
    const std::string bytes = value_bytes(d, field, view, width);
    j["values"] = base64(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    j["value_bytes"] = width;
  }
  return j;
}

PageField page_field(const Run& s, const Box& view) {
  const Design& d = s.recipe.design;
  const CurdField field = curdle(d, s.seed, view, s.generate);
  PageField out{segment_head(s, view, field), {}};
  int bits = 0;
  if (d.lattice.dimension <= 2) {
    PackedValues packed = pack_values(field, view);
    bits = packed.bits;
    out.values = std::move(packed.bytes);
  }
  out.head["value_bits"] = bits;
  return out;
}

ordered_json picture_study_json(const PictureStudy& study) {
  const FittedRecipe& f = study.fitted;
  ordered_json curds = ordered_json::array();
  for (const FittedCurd& curd : f.curds) {
    ordered_json probabilities = ordered_json::array(), stages = ordered_json::array();
    for (const StageFit& s : curd.fit.stages) {
      probabilities.push_back(probability_text(s.probability));
      stages.push_back({{"stage", s.stage},
                        {"measured", s.measured},
                        {"expected", s.expected},
                        {"expected_sd", s.expected_sd},
                        {"z", s.z},
                        {"probability", s.probability},
                        {"low", s.low},
                        {"high", s.high},
                        {"p_value", s.p_value}});
    }
    curds.push_back({{"name", curd.name},
                     {"colour", curd.colour},
                     {"probabilities", probabilities},
                     {"stages", stages},
                     {"chi_square", curd.fit.chi_square},
                     {"degrees", curd.fit.degrees},
                     {"p_value", curd.fit.p_value}});
  }
  ordered_json j;
  j["measure"] = measure_to_json(study.measured);
  j["fit"] = {{"name", f.name},
              {"lattice",
               {{"base", f.lattice.base},
                {"dimension", f.lattice.dimension},
                {"stages", f.lattice.stages},
                {"mode", std::string(to_string(f.lattice.mode))}}},
              {"field", {f.size[0], f.size[1]}},
              {"curds", curds},
              {"warnings", f.warnings},
              {"recipe_is_chain", f.recipe_is_chain},
              {"chain", f.chain ? chain_reading_json(*f.chain, f.lattice.stages) : ordered_json()},
              {"recipe_toml", f.toml}};
  return j;
}

ordered_json value_colours_json(const std::vector<std::string>& curd_colours) {
  std::vector<CurdSpec> curds;
  for (const std::string& value : curd_colours) {
    const auto colour = parse_hex_colour(value);
    if (!colour)
      throw InputError(parameter("colour"), "'" + value + "' is not a colour written #rrggbb");
    CurdSpec curd;
    curd.colour = colour;
    curds.push_back(curd);
  }
  if (curds.empty() || curds.size() > 8)
    throw InputError(parameter("colour"), "give from 1 to 8 curd colours");
  ordered_json values = ordered_json::array();
  for (const Rgb& c : value_colours(curds)) values.push_back(hex_colour(c));
  return {{"values", values}};
}

}  // namespace curdle::app
