#include "export/report/report_json.h"

#include <cmath>
#include <map>

#include "export/report/json_number.h"
#include "layout/contour.h"
#include "layout/framed_boxes.h"
#include "layout/piece.h"

namespace curdle {
namespace {

using json = nlohmann::ordered_json;

json box_json(const Box& box, int dimension) {
  json origin = json::array(), size = json::array();
  for (int d = 0; d < dimension; ++d) {
    origin.push_back(box.origin[d]);
    size.push_back(box.size[d]);
  }
  return {{"origin", origin}, {"size", size}};
}

json fit_json(const std::optional<LineFit>& fit) {
  return fit ? json{{"slope", rounded(fit->slope)}, {"r2", rounded(fit->r2, 4)}} : json(nullptr);
}

// A Markov curd: per stage, per state, the count beside its expectation; per set (each living
// state, then "living") the box counts, dimensions and extinction.
json markov_json(const MarkovReport& m) {
  json stages = json::array();
  for (const StateStageRow& s : m.stages)
    stages.push_back({{"stage", s.stage},
                      {"state", s.state},
                      {"cells", s.cells},
                      {"count", s.count},
                      {"expected_share", probability_json(s.share)},
                      {"expected", rounded(s.expected, 3)},
                      {"expected_sd", rounded(s.expected_sd, 3)},
                      {"z", s.z ? rounded(*s.z, 3) : json(nullptr)}});
  json sets = json::array();
  for (const StateSet& set : m.sets) {
    json expected = json::array();
    for (double x : set.expected_box_counts) expected.push_back(rounded(x, 3));
    sets.push_back({{"name", set.name},
                    {"box_counts", set.box_counts},
                    {"expected_box_counts", expected},
                    {"box_dimension", fit_json(set.fit)},
                    {"expected_box_dimension", fit_json(set.expected_fit)},
                    {"theory_dimension",
                     set.theory_dimension ? rounded(*set.theory_dimension) : json(nullptr)},
                    {"extinction", probability_json(set.extinction)}});
  }
  return {{"name", m.name},   {"states", m.states}, {"stationary", m.stationary},
          {"wheys", m.wheys}, {"stages", stages},   {"sets", sets}};
}

}  // namespace

json report_to_json(const Report& r) {
  json j;
  j["recipe"] = r.recipe;
  j["seed"] = r.seed;
  j["lattice"] = {{"base", r.lattice.base},
                  {"dimension", r.lattice.dimension},
                  {"stages", r.lattice.stages},
                  {"mode", std::string(to_string(r.lattice.mode))}};
  j["field"] = box_json(r.field, r.lattice.dimension);
  j["view"] = box_json(r.view, r.lattice.dimension);
  j["cells"] = r.cells;
  if (r.sd_is_approximate)
    j["note"] = "quota mode seen through a window: expected_sd is the canonical-mode value";
  json curds = json::array();
  for (const CurdReport& c : r.curds) {
    json stages = json::array();
    for (const StageRow& s : c.stages) {
      stages.push_back({{"stage", s.stage},
                        {"probability", probability_json(s.probability.value())},
                        {"probability_text", s.probability.text()},
                        {"cells", s.cells},
                        {"survivors", s.survivors},
                        {"expected", rounded(s.expected, 3)},
                        {"expected_sd", rounded(s.expected_sd, 3)},
                        {"box_count", s.box_count},
                        {"expected_box_count", rounded(s.expected_box_count, 3)},
                        {"local_dimension", rounded(s.local_dimension)},
                        {"log_ratio_dimension", rounded(s.mean_dimension)},
                        {"theory_dimension", rounded(s.theory_dimension)}});
      // Quota mode's target that the field could not hold: said, beside what was reached.
      if (s.quota_missed) stages.back()["quota_target_missed"] = *s.quota_missed;
    }
    json fit = {{"fit", c.fit ? rounded(c.fit->slope) : json(nullptr)},
                {"r2", c.fit ? rounded(c.fit->r2) : json(nullptr)},
                {"levels", c.fit ? c.fit->points : 0},
                {"expected_at_these_stages",
                 c.expected_fit ? rounded(c.expected_fit->slope) : json(nullptr)},
                {"theory", rounded(c.theory_dimension)}};
    // No limit dimension where the curd dies out almost surely: said, not a negative number.
    if (c.dies_out) fit["theory_dies_out"] = true;
    // Boxes the view cuts weighted by the share it shows (null above 2^24 cells).
    if (c.share_weighted_fit)
      fit["share_weighted"] = {
          {"fit", rounded(c.share_weighted_fit->slope)},
          {"expected_at_these_stages", c.expected_share_weighted_fit
                                           ? rounded(c.expected_share_weighted_fit->slope)
                                           : json(nullptr)}};
    else
      fit["share_weighted"] = nullptr;
    curds.push_back({{"name", c.name},
                     {"final_probability", probability_json(c.final_probability)},
                     // A cell's final survival is min(1, P_K g), g the field at its centre.
                     {"density", c.density.empty() ? json(nullptr) : json(c.density)},
                     {"roots", c.roots},
                     {"root_box_count", c.root_box_count},
                     {"stages", stages},
                     {"box_counts", c.box_counts},
                     {"box_dimension", fit}});
  }
  j["curds"] = curds;
  if (!r.markov.empty()) {
    json markov = json::array();
    for (const MarkovReport& m : r.markov) markov.push_back(markov_json(m));
    j["markov_curds"] = markov;
  }
  json values = json::array();
  for (const ValueRow& v : r.values)
    values.push_back({{"value", v.value},
                      {"label", v.label},
                      {"count", v.count},
                      {"expected", rounded(v.expected, 3)}});
  j["values"] = values;
  return j;
}

namespace {

// A building's façades: where each lies, its size, openings and units (a corner unit on the
// face that holds its middle), by value.
json facades_json(const Layout& layout) {
  std::map<const SurfaceFrame*, std::vector<uint64_t>> units;
  for (const Element& e : layout.elements) {
    auto& counts = units[framed_facade(layout, e)];
    counts.resize(layout.legend.size());
    ++counts[e.value];
  }
  json out = json::array();
  for (const SurfaceFrame& f : layout.frames()) {
    double open = 0;
    size_t openings = 0;
    for (size_t i = 0; i < layout.openings_given; ++i) {
      const Rect& o = layout.openings[i];
      if (o.x >= f.start - 1e-6 && o.right() <= f.start + f.length + 1e-6)
        ++openings, open += o.area();
    }
    json by_value = json::array();
    uint64_t total = 0;
    const std::vector<uint64_t>& counts = units[&f];
    for (uint32_t v = 0; v < counts.size(); ++v) {
      total += counts[v];
      by_value.push_back({{"value", v}, {"label", layout.legend[v].label}, {"units", counts[v]}});
    }
    out.push_back(
        {{"name", f.name},
         {"index", f.index},
         {"facing_degrees", rounded(f.facing, 3)},
         {"start_mm", f.start},
         {"length_mm", f.length},
         {"height_mm", f.height > 0 ? f.height : layout.height},
         {"curved", f.bulge != 0},
         {"area_m2", rounded(f.length * (f.height > 0 ? f.height : layout.height) / 1e6, 6)},
         {"openings", openings},
         {"open_area_m2", rounded(open / 1e6, 6)},
         {"turn_at_end_degrees", rounded(f.turn_at_end, 3)},
         {"units", total},
         {"units_by_value", by_value}});
  }
  return out;
}

// Where the layout lies in the drawing it was read from: the datum's drawing coordinates in the
// drawing's units.
json site_drawing_json(const Layout& layout) {
  const SiteFrame& f = *layout.site_frame;
  json j = {{"file", f.file},
            {"units", f.unit_name},
            {"mm_per_unit", f.unit_mm},
            {"datum", {f.datum[0], f.datum[1]}},
            {"datum_note", "the layout's (0, 0) as a point of the drawing, in its units"}};
  return j;
}

// The outline read from the drawing, with its true arcs: its area and extent, to check a
// reading against CAD's.
json site_outline_json(const Layout& layout) {
  const Contour c =
      !layout.outline_contour.empty() ? layout.outline_contour : contour_of(layout.outline);
  const Rect b = contour_bounds(c);
  return {{"area_m2", contour_area(c) / 1e6}, {"box_mm", {b.x, b.y, b.right(), b.top()}}};
}

}  // namespace

json report_to_json(const Report& report, const Layout& layout) {
  json j = report_to_json(report);
  j["layout"] = {{"element_type", layout.element_type}, {"width_mm", layout.width},
                 {"height_mm", layout.height},          {"elements", layout.elements.size()},
                 {"cut", cut_elements(layout)},         {"omitted_over_openings", layout.omitted},
                 {"open_area", layout.open_area},       {"notes", layout.notes},
                 {"rule_violations", layout.violations}};
  if (!layout.site.empty()) j["layout"]["site"] = layout.site;
  if (layout.site_frame) j["layout"]["site_drawing"] = site_drawing_json(layout);
  if (!layout.site.empty() && (!layout.outline_contour.empty() || !layout.outline.empty()))
    j["layout"]["site_outline"] = site_outline_json(layout);
  if (layout.envelope) j["layout"]["facades"] = facades_json(layout);
  if (layout.fabrication) {
    json sheets = json::array();
    for (const FabricationSheet& sheet : layout.sheets()) {
      json tools = json::object();
      for (const auto& [tool, count] : sheet.tools) tools[tool] = count;
      sheets.push_back({{"id", sheet.id},
                        {"x_mm", sheet.area.x},
                        {"y_mm", sheet.area.y},
                        {"width_mm", sheet.area.w},
                        {"height_mm", sheet.area.h},
                        {"open_area", sheet.open_area},
                        {"openings_per_tool", tools}});
    }
    j["layout"]["sheets"] = sheets;
  }
  if (!layout.zones.empty()) {
    // Per zone: its area and the elements whose centre it holds, by value (all of its own
    // value for a value zone); an excluded zone also the pieces cut along it.
    json zones = json::array();
    for (const ZoneCount& z : layout.zones) {
      json by_value = json::array();
      uint64_t total = 0;
      for (uint32_t v = 0; v < z.by_value.size(); ++v) {
        total += z.by_value[v];
        by_value.push_back({{"value", v},
                            {"label", v < layout.legend.size() ? layout.legend[v].label : ""},
                            {"elements", z.by_value[v]}});
      }
      json zone = {{"name", z.name},
                   {"rule", z.rule == ZoneRule::exclude ? "exclude" : "value"},
                   {"area_m2", z.area / 1e6},
                   {"elements", total},
                   {"by_value", by_value}};
      if (z.rule == ZoneRule::value) zone["value"] = z.value;
      if (z.rule == ZoneRule::exclude) zone["cut_along_it"] = z.cut;
      zones.push_back(zone);
    }
    j["layout"]["zones"] = zones;
  }
  return j;
}

}  // namespace curdle
