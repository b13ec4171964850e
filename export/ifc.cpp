#include "export/ifc.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "curdle/markov.h"
#include "curdle/palette.h"
#include "curdle/stop.h"
#include "export/schedule.h"
#include "export/step_file.h"
#include "layout/contour.h"
#include "layout/piece.h"
#include "layout/union.h"

namespace curdle {
namespace {

std::string real(double v) { return step_real(v); }
std::string ref(int64_t id) { return fmt::format("#{}", id); }
std::string text(std::string_view s) { return step_string(s); }

// What an element becomes in the model.
struct IfcClass {
  const char* entity;      // IFCCOVERING, ...
  const char* predefined;  // its PredefinedType
  bool typed = false;      // grouped by an IfcCoveringType
};

IfcClass class_of(const Layout& layout, const Element& e) {
  switch (e.form) {
    case ElementForm::opening:
      return {"IFCOPENINGELEMENT", ".OPENING."};
    case ElementForm::block:
      return {"IFCBUILDINGELEMENTPROXY", ".ELEMENT."};
    case ElementForm::object:
      if (e.circle) return {"IFCGEOGRAPHICELEMENT", ".USERDEFINED."};
      if (e.stands) return {"IFCFURNITURE", ".USERDEFINED."};
      return {"IFCCOVERING", ".FLOORING."};
    case ElementForm::piece:
    case ElementForm::cut_piece:
      break;
  }
  return {"IFCCOVERING", layout.kind->upright() ? ".CLADDING." : ".FLOORING.", true};
}

// The model under construction: shared geometry, the spatial structure, and what the closing
// relations gather (elements per material, per type, per sheet).
class IfcModel {
 public:
  IfcModel(std::ostream& out, const Layout& layout)
      : w_(out, "layout.ifc", "IFC4", "ReferenceView_V1.2"), l_(layout) {
    const Box& v = layout.view;
    key_ = fmt::format("{}/{}/{},{},{}+{}x{}x{}/", layout.source.recipe, layout.source.seed,
                       v.origin[0], v.origin[1], v.origin[2], v.size[0], v.size[1], v.size[2]);
  }

  void write() {
    context();
    spatial_structure();
    if (l_.kind->ground() == Ground::sheet) sheets();
    arc_annotations();
    for (size_t i = 0; i < l_.elements.size(); ++i) {
      stop_point();
      element(l_.elements[i], i);
    }
    closing_relations();
    w_.finish();
  }

 private:
  std::string guid(std::string_view what) const { return text(ifc_guid(key_ + std::string(what))); }
  int64_t add(const std::string& s) { return w_.add(s); }
  int64_t point(double x, double y) {
    return add(fmt::format("IFCCARTESIANPOINT(({},{}))", real(x), real(y)));
  }
  int64_t point(double x, double y, double z) {
    return add(fmt::format("IFCCARTESIANPOINT(({},{},{}))", real(x), real(y), real(z)));
  }
  int64_t direction(double x, double y, double z) {
    return add(fmt::format("IFCDIRECTION(({},{},{}))", real(x), real(y), real(z)));
  }

  void context() {
    origin_ = point(0, 0, 0);
    z_ = direction(0, 0, 1);
    world_ = add(fmt::format("IFCAXIS2PLACEMENT3D({},$,$)", ref(origin_)));
    // Upright surfaces are drawn in their own plane: layout x along X, layout y up Z, and the
    // thickness out of the wall towards -Y (the street side).
    const int64_t out_of_wall = direction(0, -1, 0), along = direction(1, 0, 0);
    plane_ = l_.kind->upright() ? add(fmt::format("IFCAXIS2PLACEMENT3D({},{},{})", ref(origin_),
                                                  ref(out_of_wall), ref(along)))
                                : world_;
    const int64_t model =
        add(fmt::format("IFCGEOMETRICREPRESENTATIONCONTEXT($,'Model',3,1.E-05,{},$)", ref(world_)));
    body_ = add(fmt::format(
        "IFCGEOMETRICREPRESENTATIONSUBCONTEXT('Body','Model',*,*,*,*,{},$,.MODEL_VIEW.,$)",
        ref(model)));
    if (has_arc_contours())
      annotation_ = add(fmt::format(
          "IFCGEOMETRICREPRESENTATIONSUBCONTEXT('Annotation','Plan',*,*,*,*,{},$,.PLAN_VIEW.,$)",
          ref(model)));
    // Added one by one: arguments of one call are evaluated in no fixed order, and the bytes
    // must not depend on the compiler.
    const std::vector<int64_t> unit_ids{add("IFCSIUNIT(*,.LENGTHUNIT.,.MILLI.,.METRE.)"),
                                        add("IFCSIUNIT(*,.AREAUNIT.,$,.SQUARE_METRE.)"),
                                        add("IFCSIUNIT(*,.VOLUMEUNIT.,$,.CUBIC_METRE.)"),
                                        add("IFCSIUNIT(*,.PLANEANGLEUNIT.,$,.RADIAN.)")};
    const int64_t units = add("IFCUNITASSIGNMENT(" + step_refs(unit_ids) + ")");
    const std::string description =
        l_.source.description.empty() ? "$" : text(l_.source.description);
    project_ = add(fmt::format("IFCPROJECT({},$,{},{},$,$,$,({}),{})", guid("project"),
                               text(l_.source.recipe), description, ref(model), ref(units)));
    recipe_properties();
  }

  // How to make the model again: recipe, seed, lattice and the window of cells laid.
  void recipe_properties() {
    const Provenance& s = l_.source;
    const Box& v = l_.view;
    std::vector<int64_t> props{
        label("Recipe", s.recipe),
        label("Seed", std::to_string(s.seed)),
        integer("LatticeBase", s.lattice.base),
        integer("LatticeDimension", s.lattice.dimension),
        integer("LatticeStages", s.lattice.stages),
        label("LatticeMode", std::string(to_string(s.lattice.mode))),
        label("Window", fmt::format("{},{},{} + {} x {} x {} cells", v.origin[0], v.origin[1],
                                    v.origin[2], v.size[0], v.size[1], v.size[2]))};
    std::string curds;
    for (const CurdGroup& g : curd_groups(s.curds)) {
      curds += (curds.empty() ? "" : ", ") + s.curds[g.first].name;
      if (g.chain)
        curds += " (Markov: " + fmt::format("{}", fmt::join(g.chain->states, ", ")) + ")";
    }
    props.push_back(label("Curds", curds));
    const int64_t set = add(
        fmt::format("IFCPROPERTYSET({},$,'Curdle_Recipe',$,{})", guid("recipe"), step_refs(props)));
    add(fmt::format("IFCRELDEFINESBYPROPERTIES({},$,$,$,({}),{})", guid("recipe-rel"),
                    ref(project_), ref(set)));
  }

  // A property of a set: its name and its typed value ("IFCINTEGER(3)").
  int64_t property(const std::string& name, const std::string& value) {
    return add(fmt::format("IFCPROPERTYSINGLEVALUE({},$,{},$)", text(name), value));
  }
  int64_t label(const std::string& name, const std::string& value) {
    return property(name, "IFCLABEL(" + text(value) + ")");
  }
  int64_t integer(const std::string& name, int64_t value) {
    return property(name, fmt::format("IFCINTEGER({})", value));
  }
  int64_t length(const std::string& name, double value) {
    return property(name, "IFCPOSITIVELENGTHMEASURE(" + real(value) + ")");
  }

  // Ground works stand on a site; façades, screens and blocks in a building's storey.
  void spatial_structure() {
    const int64_t site_place = add(fmt::format("IFCLOCALPLACEMENT($,{})", ref(world_)));
    const int64_t site = add(fmt::format("IFCSITE({},$,'Site',$,$,{},$,$,.ELEMENT.,$,$,$,$,$)",
                                         guid("site"), ref(site_place)));
    add(fmt::format("IFCRELAGGREGATES({},$,$,$,{},({}))", guid("project-site"), ref(project_),
                    ref(site)));
    container_ = site, container_place_ = site_place;
    const bool ground_works = !l_.kind->upright() && l_.kind->ground() != Ground::sheet &&
                              l_.kind->depiction() != Depiction::views;
    if (ground_works) return;
    const int64_t building_place =
        add(fmt::format("IFCLOCALPLACEMENT({},{})", ref(site_place), ref(world_)));
    const int64_t building =
        add(fmt::format("IFCBUILDING({},$,'Building',$,$,{},$,$,.ELEMENT.,$,$,$)", guid("building"),
                        ref(building_place)));
    add(fmt::format("IFCRELAGGREGATES({},$,$,$,{},({}))", guid("site-building"), ref(site),
                    ref(building)));
    const int64_t storey_place =
        add(fmt::format("IFCLOCALPLACEMENT({},{})", ref(building_place), ref(world_)));
    const int64_t storey =
        add(fmt::format("IFCBUILDINGSTOREY({},$,'Level 0',$,$,{},$,$,.ELEMENT.,0.)", guid("storey"),
                        ref(storey_place)));
    add(fmt::format("IFCRELAGGREGATES({},$,$,$,{},({}))", guid("building-storey"), ref(building),
                    ref(storey)));
    container_ = storey, container_place_ = storey_place;
  }

  // Profiles, in the surface's plane, in millimetres from its bottom-left corner.
  int64_t rectangle(const Rect& r) {
    const int64_t at =
        add(fmt::format("IFCAXIS2PLACEMENT2D({},$)", ref(point(r.x + r.w / 2, r.y + r.h / 2))));
    return add(
        fmt::format("IFCRECTANGLEPROFILEDEF(.AREA.,$,{},{},{})", ref(at), real(r.w), real(r.h)));
  }
  // A circle as a polygon within the layout's chord tolerance, as the DXF and glTF draw it,
  // with corners at its four extremes so that its extent is the circle's in every reader
  // (readers tessellate IfcCircleProfileDef each their own way: web-ifc's missed by 0.3 mm).
  int64_t circle(const Circle& c) {
    const double r = c.d / 2, pi = 3.14159265358979323846;
    const double step = 2 * std::acos(std::max(-1.0, 1 - l_.chord_tolerance / r));
    const int quarter = std::clamp(static_cast<int>(std::ceil(pi / 2 / step)), 2, 256);
    Ring ring;
    for (int k = 0; k < 4 * quarter; ++k) {
      const double a = pi / 2 * k / quarter;
      // The extremes exactly, not through sin and cos.
      const int q = k % quarter == 0 ? k / quarter : -1;
      ring.push_back(q < 0 ? std::array<double, 2>{c.cx + r * std::cos(a), c.cy + r * std::sin(a)}
                           : std::array<double, 2>{c.cx + (q == 0   ? r
                                                           : q == 2 ? -r
                                                                    : 0),
                                                   c.cy + (q == 1   ? r
                                                           : q == 3 ? -r
                                                                    : 0)});
    }
    return add(fmt::format("IFCARBITRARYCLOSEDPROFILEDEF(.AREA.,$,{})", ref(polyline(ring))));
  }
  int64_t polyline(const Ring& ring) {
    std::vector<int64_t> points;
    for (const auto& v : ring) points.push_back(point(v[0], v[1]));
    points.push_back(points.front());
    return add("IFCPOLYLINE(" + step_refs(points) + ")");
  }
  // One outer ring with the islands inside it (outline_parts splits an outline so).
  int64_t outline_profile(const Outline& part) {
    const int64_t outer = polyline(part.rings.front());
    if (part.rings.size() == 1)
      return add(fmt::format("IFCARBITRARYCLOSEDPROFILEDEF(.AREA.,$,{})", ref(outer)));
    std::vector<int64_t> inner;
    for (size_t i = 1; i < part.rings.size(); ++i) inner.push_back(polyline(part.rings[i]));
    return add(fmt::format("IFCARBITRARYPROFILEDEFWITHVOIDS(.AREA.,$,{},{})", ref(outer),
                           step_refs(inner)));
  }

  // A solid from `base` to `base + depth` out of the surface's plane, in `colour`.
  int64_t solid(int64_t profile, double base, double depth, const Rgb& colour) {
    const int64_t s = add(fmt::format("IFCEXTRUDEDAREASOLID({},{},{},{})", ref(profile),
                                      ref(base_placement(base)), ref(z_), real(depth)));
    add(fmt::format("IFCSTYLEDITEM({},({}),$)", ref(s), ref(style(colour))));
    return s;
  }
  int64_t base_placement(double base) {
    if (base == 0) return world_;
    auto it = bases_.find(base);
    if (it != bases_.end()) return it->second;
    return bases_[base] = add(fmt::format("IFCAXIS2PLACEMENT3D({},$,$)", ref(point(0, 0, base))));
  }
  int64_t style(const Rgb& c) {
    const uint32_t key = uint32_t{c.r} << 16 | uint32_t{c.g} << 8 | c.b;
    auto it = styles_.find(key);
    if (it != styles_.end()) return it->second;
    const int64_t colour = add(fmt::format("IFCCOLOURRGB($,{},{},{})", real(c.r / 255.0),
                                           real(c.g / 255.0), real(c.b / 255.0)));
    const int64_t shading = add(fmt::format("IFCSURFACESTYLESHADING({},0.)", ref(colour)));
    return styles_[key] = add(
               fmt::format("IFCSURFACESTYLE({},.BOTH.,({}))", text(hex_colour(c)), ref(shading)));
  }

  // The element's solids as laid.
  std::vector<int64_t> solids(const Element& e, const Rgb& colour) {
    const double t = l_.thickness;
    std::vector<int64_t> out;
    if (e.form == ElementForm::block) {
      const double w = l_.module_w, d = l_.module_h, h = l_.level_height;
      const Rect plan{static_cast<double>(e.cell_x - l_.view.origin[0]) * w,
                      static_cast<double>(e.cell_y - l_.view.origin[1]) * d, w, d};
      out.push_back(
          solid(rectangle(plan), static_cast<double>(e.cell_z - l_.view.origin[2]) * h, h, colour));
      return out;
    }
    if (e.form == ElementForm::opening) {  // through the sheet, a millimetre beyond each face
      if (e.circle) out.push_back(solid(circle(*e.circle), -1, t + 2, colour));
      if (e.outline)
        for (const Outline& part : outline_parts(*e.outline))
          out.push_back(solid(outline_profile(part), -1, t + 2, colour));
      return out;
    }
    if (e.circle) {  // a tree: a trunk of 200 mm to 2.2 m, then its canopy as a drum
      out.push_back(
          solid(circle(Circle{e.circle->cx, e.circle->cy, 200}), t, 2200, Rgb{92, 64, 44}));
      out.push_back(solid(circle(*e.circle), t + 2200, e.circle->d, colour));
      return out;
    }
    const double base = e.stands ? t : 0, depth = e.stands ? 450 : t;
    if (e.outline) {
      for (const Outline& part : outline_parts(*e.outline))
        out.push_back(solid(outline_profile(part), base, depth, colour));
      return out;
    }
    for (const Rect& r : e.shape) out.push_back(solid(rectangle(r), base, depth, colour));
    return out;
  }

  // The fabrication sheets a perforated surface is cut into, each a plate its openings void.
  void sheets() {
    const double t = l_.thickness;
    const Rgb metal{201, 205, 210};
    const int64_t material =
        add(fmt::format("IFCMATERIAL({},$,'metal')", text(fmt::format("sheet, {} mm", real(t)))));
    for (const Layout::FabricationSheet& s : l_.sheets) {
      std::vector<int64_t> items;
      if (s.outline.empty()) {
        items.push_back(solid(rectangle(s.area), 0, t, metal));
      } else {
        Outline whole;
        whole.rings = s.outline;
        for (const Outline& part : outline_parts(whole))
          items.push_back(solid(outline_profile(part), 0, t, metal));
      }
      const int64_t where = placement(), body = shape(items);
      const int64_t plate =
          add(fmt::format("IFCPLATE({},$,{},$,'perforated sheet',{},{},{},.SHEET.)",
                          guid("sheet " + s.id), text(s.id), ref(where), ref(body), text(s.id)));
      contained_.push_back(plate);
      sheet_plates_.push_back(plate);
    }
    add(fmt::format("IFCRELASSOCIATESMATERIAL({},$,$,$,{},{})", guid("sheet-material"),
                    step_refs(sheet_plates_), ref(material)));
  }

  int64_t placement() {
    return add(fmt::format("IFCLOCALPLACEMENT({},{})", ref(container_place_), ref(plane_)));
  }

  bool has_arc_contours() const {
    return !l_.outline_contour.empty() ||
           std::any_of(l_.zones.begin(), l_.zones.end(),
                       [](const ZoneCount& z) { return !z.contour.empty(); });
  }
  // A contour as an IfcIndexedPolyCurve: straight edges as IfcLineIndex, arcs as IfcArcIndex
  // through their middle, so that a reader draws the true arc rather than its chords.
  int64_t indexed_curve(const Contour& c) {
    std::vector<std::string> points, segments;
    auto index_of = [&](double x, double y) {
      points.push_back(fmt::format("({},{})", real(x), real(y)));
      return points.size();
    };
    index_of(c[0].x, c[0].y);
    for (size_t i = 0; i < c.size(); ++i) {
      const size_t from = points.size();
      const ContourVertex& next = c[(i + 1) % c.size()];
      const size_t to = i + 1 < c.size() ? 0 : 1;  // the last edge closes on the first point
      if (c[i].bulge == 0) {
        const size_t end = to ? to : index_of(next.x, next.y);
        segments.push_back(fmt::format("IFCLINEINDEX(({},{}))", from, end));
        continue;
      }
      const Arc a = arc_between(c[i], next);
      const double mid = a.start_angle() + a.sweep / 2;
      const size_t middle =
          index_of(a.centre[0] + a.radius * std::cos(mid), a.centre[1] + a.radius * std::sin(mid));
      const size_t end = to ? to : index_of(next.x, next.y);
      segments.push_back(fmt::format("IFCARCINDEX(({},{},{}))", from, middle, end));
    }
    std::string list;
    for (const std::string& p : points) list += (list.empty() ? "" : ",") + p;
    std::string segs;
    for (const std::string& sgm : segments) segs += (segs.empty() ? "" : ",") + sgm;
    const int64_t coordinates = add("IFCCARTESIANPOINTLIST2D((" + list + "))");
    return add(fmt::format("IFCINDEXEDPOLYCURVE({},({}),.F.)", ref(coordinates), segs));
  }
  // The outline and zones whose edges are arcs, as annotations a setter-out or a coordinator
  // reads them by: their curves in the surface's plane, arcs kept.
  void arc_annotations() {
    if (!has_arc_contours()) return;
    auto annotate = [&](const std::string& name, const Contour& c) {
      const int64_t rep = add(fmt::format("IFCSHAPEREPRESENTATION({},'Annotation','Curve2D',({}))",
                                          ref(annotation_), ref(indexed_curve(c))));
      const int64_t shape = add(fmt::format("IFCPRODUCTDEFINITIONSHAPE($,$,({}))", ref(rep)));
      contained_.push_back(
          add(fmt::format("IFCANNOTATION({},$,{},$,'setting out',{},{})",
                          guid("annotation " + name), text(name), ref(placement()), ref(shape))));
    };
    if (!l_.outline_contour.empty()) annotate("Outline", l_.outline_contour);
    for (const ZoneCount& z : l_.zones)
      if (!z.contour.empty()) annotate("Zone " + z.name, z.contour);
  }
  int64_t shape(const std::vector<int64_t>& items) {
    const int64_t rep = add(fmt::format("IFCSHAPEREPRESENTATION({},'Body','SweptSolid',{})",
                                        ref(body_), step_refs(items)));
    return add(fmt::format("IFCPRODUCTDEFINITIONSHAPE($,$,({}))", ref(rep)));
  }

  void element(const Element& e, size_t index) {
    const IfcClass c = class_of(l_, e);
    const Rgb& colour = piece_colour(l_, e);
    const int64_t product_shape = shape(solids(e, colour));
    const std::string type = element_type_of(l_, e);
    const int64_t where = placement();
    const int64_t id =
        add(fmt::format("{}({},$,{},$,{},{},{},{},{})", c.entity, guid(e.id), text(e.id),
                        text(type), ref(where), ref(product_shape), text(e.id), c.predefined));
    if (e.form == ElementForm::opening) {
      if (e.sheet >= 0)
        add(fmt::format("IFCRELVOIDSELEMENT({},$,$,$,{},{})", guid("void " + e.id),
                        ref(sheet_plates_[static_cast<size_t>(e.sheet)]), ref(id)));
    } else {
      contained_.push_back(id);
    }
    const std::string& material = piece_material(l_, e);
    materials_[material].push_back(id);
    if (c.typed) {
      CoveringType& covering = types_[{material, stock_size_of(l_, e)}];
      covering.stock = {e.stock_w, e.stock_h};  // one stock size per type: the same for every piece
      covering.elements.push_back(id);
    }
    properties(e, index, id);
    quantities(e, id);
  }

  void properties(const Element& e, size_t index, int64_t id) {
    std::string bits;
    for (size_t k = 0; k < l_.source.curds.size(); ++k) bits += (e.value >> k & 1) ? '1' : '0';
    std::vector<int64_t> props{integer("Value", e.value),
                               label("CurdBits", bits),
                               integer("Row", e.row),
                               integer("Column", e.column),
                               label("Lot", lot_text(l_, e, index)),
                               property("Cut", e.cut ? "IFCBOOLEAN(.T.)" : "IFCBOOLEAN(.F.)"),
                               label("Material", piece_material(l_, e)),
                               label("StockSize", stock_size_of(l_, e))};
    if (e.form == ElementForm::block)
      props.push_back(integer("Level", e.cell_z - l_.view.origin[2]));
    const int64_t set = add(fmt::format("IFCPROPERTYSET({},$,'Curdle_Element',$,{})",
                                        guid("pset " + e.id), step_refs(props)));
    add(fmt::format("IFCRELDEFINESBYPROPERTIES({},$,$,$,({}),{})", guid("pset-rel " + e.id),
                    ref(id), ref(set)));
  }

  void quantities(const Element& e, int64_t id) {
    const Rect b = laid_bounds(e);
    const double t = e.form == ElementForm::block ? l_.level_height : l_.thickness;
    std::vector<int64_t> q{
        add(fmt::format("IFCQUANTITYLENGTH('Length',$,$,{},$)", real(b.w))),
        add(fmt::format("IFCQUANTITYLENGTH('Width',$,$,{},$)", real(b.h))),
        add(fmt::format("IFCQUANTITYLENGTH('Thickness',$,$,{},$)", real(t))),
        add(fmt::format("IFCQUANTITYAREA('NetArea',$,$,{},$)", real(e.area() / 1e6)))};
    const int64_t set = add(fmt::format("IFCELEMENTQUANTITY({},$,'BaseQuantities',$,$,{})",
                                        guid("qto " + e.id), step_refs(q)));
    add(fmt::format("IFCRELDEFINESBYPROPERTIES({},$,$,$,({}),{})", guid("qto-rel " + e.id), ref(id),
                    ref(set)));
  }

  // What groups elements: containment, materials and covering types.
  void closing_relations() {
    if (!contained_.empty())
      add(fmt::format("IFCRELCONTAINEDINSPATIALSTRUCTURE({},$,$,$,{},{})", guid("contained"),
                      step_refs(contained_), ref(container_)));
    for (const auto& [name, ids] : materials_) {
      const int64_t m = add(fmt::format("IFCMATERIAL({},$,$)", text(name)));
      add(fmt::format("IFCRELASSOCIATESMATERIAL({},$,$,$,{},{})", guid("material " + name),
                      step_refs(ids), ref(m)));
    }
    const char* predefined = l_.kind->upright() ? ".CLADDING." : ".FLOORING.";
    for (const auto& [key, covering] : types_) {
      const auto& [material, size] = key;
      std::vector<int64_t> sets;
      if (covering.stock[0] > 0) {
        const std::vector<int64_t> tiling{length("TileLength", covering.stock[0]),
                                          length("TileWidth", covering.stock[1])};
        sets.push_back(add(fmt::format("IFCPROPERTYSET({},$,'Pset_Tiling',$,{})",
                                       guid("tiling " + material + size), step_refs(tiling))));
      }
      const std::string name = material + ", " + size;
      const int64_t type = add(
          fmt::format("IFCCOVERINGTYPE({},$,{},$,$,{},$,$,{},{})", guid("type " + name), text(name),
                      sets.empty() ? "$" : step_refs(sets), text(l_.element_type), predefined));
      add(fmt::format("IFCRELDEFINESBYTYPE({},$,$,$,{},{})", guid("type-rel " + name),
                      step_refs(covering.elements), ref(type)));
    }
  }

  // The pieces of one material and stock size, and that size.
  struct CoveringType {
    std::array<double, 2> stock{0, 0};
    std::vector<int64_t> elements;
  };

  StepWriter w_;
  const Layout& l_;
  std::string key_;
  int64_t origin_ = 0, z_ = 0, world_ = 0, plane_ = 0, body_ = 0, annotation_ = 0, project_ = 0;
  int64_t container_ = 0, container_place_ = 0;
  std::map<double, int64_t> bases_;
  std::map<uint32_t, int64_t> styles_;
  std::vector<int64_t> contained_, sheet_plates_;
  std::map<std::string, std::vector<int64_t>> materials_;
  std::map<std::pair<std::string, std::string>, CoveringType> types_;
};

}  // namespace

void write_layout_ifc(std::ostream& out, const Layout& layout) { IfcModel(out, layout).write(); }

}  // namespace curdle
