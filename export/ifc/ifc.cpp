#include "export/ifc/ifc.h"

#include <fmt/compile.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

#include "curdle/markov.h"
#include "curdle/palette.h"
#include "curdle/stop.h"
#include "export/ifc/ifc_envelope.h"
#include "export/ifc/ifc_geometry.h"
#include "export/ifc/ifc_screen.h"
#include "export/ifc/ifc_standard_sets.h"
#include "export/ifc/punched_sheets.h"
#include "export/ifc/step_file.h"
#include "layout/contour.h"
#include "layout/framed_sheet.h"
#include "layout/piece.h"
#include "layout/piece_rows.h"
#include "layout/standing_body.h"
#include "layout/union.h"
#include "layout/zone.h"

namespace curdle {
namespace {

using step::real;
using step::ref;
using step::text;

// The model under construction: shared geometry, the spatial structure, and what the closing
// relations gather (elements per material, per type, per sheet).
class IfcModel {
 public:
  IfcModel(std::ostream& out, const Layout& layout)
      : w_(out, "layout.ifc", "IFC4", "ReferenceView_V1.2"),
        g_(w_, layout.chord_tolerance),
        l_(layout),
        envelope_(w_, g_, layout, [this](std::string_view what) { return root(what); }) {
    const Box& v = layout.view;
    guids_ = IfcGuidSource(fmt::format("{}/{}/{},{},{}+{}x{}x{}/", layout.source.recipe,
                                       layout.source.seed, v.origin[0], v.origin[1], v.origin[2],
                                       v.size[0], v.size[1], v.size[2]));
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
    if (l_.envelope && l_.kind->ground() != Ground::sheet)  // a screen has no walls
      for (const auto& [id, base] : envelope_.walls(container_place_, parts_))
        contained_in(base).push_back(id);
    closing_relations();
    w_.finish();
  }

 private:
  // A rooted entity's first attributes: its GlobalId (from what it is, `what` then `more`)
  // and the model's one owner history.
  StepRoot root(std::string_view what, std::string_view more = {}) const {
    return {guids_.guid(what, more), owner_};
  }
  // A property or quantity, written once for every set that holds the same one (IFC lets a
  // property stand in many sets): most pieces share their material, lot, size and area, and
  // the pavilion's model is a third smaller for it.
  template <typename Format, typename... Args>
  int64_t shared(const Format& format, Args&&... args) {  // a compiled format, as add's
    scratch_.clear();
    fmt::format_to(fmt::appender(scratch_), format, std::forward<Args>(args)...);
    const std::string_view text(scratch_.data(), scratch_.size());
    const auto it = shared_.find(text);
    if (it != shared_.end()) return it->second;
    return shared_[std::string(text)] = w_.add(text);
  }
  void context() {
    world_ = g_.world();
    // Upright surfaces are drawn in their own plane: layout x along X, layout y up Z, and the
    // thickness out of the wall towards -Y (the street side).
    if (l_.kind->upright()) {
      out_of_wall_ = g_.direction(0, -1, 0);
      along_ = g_.direction(1, 0, 0);
    }
    const int64_t model = w_.add(
        FMT_COMPILE("IFCGEOMETRICREPRESENTATIONCONTEXT($,'Model',3,1.E-05,{},$)"), ref(world_));
    g_.set_body_context(w_.add(
        FMT_COMPILE(
            "IFCGEOMETRICREPRESENTATIONSUBCONTEXT('Body','Model',*,*,*,*,{},$,.MODEL_VIEW.,$)"),
        ref(model)));
    if (has_arc_contours())
      annotation_ = w_.add(FMT_COMPILE("IFCGEOMETRICREPRESENTATIONSUBCONTEXT('Annotation','Plan',*,"
                                       "*,*,*,{},$,.PLAN_VIEW.,$)"),
                           ref(model));
    if (l_.kind->ground() == Ground::sheet)
      hole_context_ = w_.add(FMT_COMPILE("IFCGEOMETRICREPRESENTATIONSUBCONTEXT('Annotation','Model'"
                                         ",*,*,*,*,{},$,.MODEL_VIEW.,$)"),
                             ref(model));
    // Added one by one: arguments of one call are evaluated in no fixed order, and the bytes
    // must not depend on the compiler.
    const std::vector<int64_t> unit_ids{w_.add("IFCSIUNIT(*,.LENGTHUNIT.,.MILLI.,.METRE.)"),
                                        w_.add("IFCSIUNIT(*,.AREAUNIT.,$,.SQUARE_METRE.)"),
                                        w_.add("IFCSIUNIT(*,.VOLUMEUNIT.,$,.CUBIC_METRE.)"),
                                        w_.add("IFCSIUNIT(*,.PLANEANGLEUNIT.,$,.RADIAN.)")};
    const int64_t units = w_.add("IFCUNITASSIGNMENT(" + step_refs(unit_ids) + ")");
    owner_history();
    const std::string description =
        l_.source.description.empty() ? std::string("$") : step_string(l_.source.description);
    project_ = w_.add(FMT_COMPILE("IFCPROJECT({},{},{},$,$,$,({}),{})"), root("project"),
                      text(l_.source.recipe), description, ref(model), ref(units));
    map_conversion(model);
    recipe_properties();
  }

  // [layout.georef]: the model's origin (the layout's datum) on the projected CRS, its x axis
  // turned by the rotation, millimetres to the map's metres, as BIM coordinators place a model.
  void map_conversion(int64_t model) {
    if (!l_.georef) return;
    const Georef& g = *l_.georef;
    const int64_t metre = w_.add("IFCSIUNIT(*,.LENGTHUNIT.,$,.METRE.)");
    const int64_t crs = w_.add(FMT_COMPILE("IFCPROJECTEDCRS({},$,$,$,$,$,{})"),
                               text(fmt::format("EPSG:{}", g.epsg)), ref(metre));
    const double turn = g.rotation * 3.14159265358979323846 / 180;
    w_.add(FMT_COMPILE("IFCMAPCONVERSION({},{},{},{},0.,{},{},0.001)"), ref(model), ref(crs),
           real(g.easting), real(g.northing), real(std::cos(turn)), real(std::sin(turn)));
  }

  // Who made the model and when, as Revit and Solibri expect of every rooted entity: curdle, at
  // the STEP header's fixed time (2000-01-01), so that the same run gives the same bytes.
  void owner_history() {
    const int64_t person = w_.add("IFCPERSON($,$,'curdle',$,$,$,$,$)");
    const int64_t organisation = w_.add("IFCORGANIZATION($,'curdle',$,$,$)");
    const int64_t both =
        w_.add(FMT_COMPILE("IFCPERSONANDORGANIZATION({},{},$)"), ref(person), ref(organisation));
    const int64_t application = w_.add(FMT_COMPILE("IFCAPPLICATION({},{},'curdle','curdle')"),
                                       ref(organisation), text(CURDLE_VERSION));
    owner_ = w_.add(FMT_COMPILE("IFCOWNERHISTORY({},{},$,.NOCHANGE.,$,$,$,946684800)"), ref(both),
                    ref(application));
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
    const int64_t set = w_.add(FMT_COMPILE("IFCPROPERTYSET({},'Curdle_Recipe',$,{})"),
                               root("recipe"), step_refs(props));
    w_.add(FMT_COMPILE("IFCRELDEFINESBYPROPERTIES({},$,$,({}),{})"), root("recipe-rel"),
           ref(project_), ref(set));
  }

  // A property of a set: its name and its typed value ("IFCINTEGER(3)").
  int64_t property(std::string_view name, std::string_view value) {
    return shared(FMT_COMPILE("IFCPROPERTYSINGLEVALUE({},$,{},$)"), text(name), value);
  }
  int64_t label(std::string_view name, std::string_view value) {
    return shared(FMT_COMPILE("IFCPROPERTYSINGLEVALUE({},$,IFCLABEL({}),$)"), text(name),
                  text(value));
  }
  int64_t integer(std::string_view name, int64_t value) {
    return shared(FMT_COMPILE("IFCPROPERTYSINGLEVALUE({},$,IFCINTEGER({}),$)"), text(name), value);
  }
  int64_t length(std::string_view name, double value) {
    return shared(FMT_COMPILE("IFCPROPERTYSINGLEVALUE({},$,IFCPOSITIVELENGTHMEASURE({}),$)"),
                  text(name), real(value));
  }

  // Façades, screens and blocks stand in a building's storey. Ground works stand in an external
  // space on the site (IfcSpace .EXTERNAL.): IFC4 has no facility part, and a storey would
  // invent a building where there is none; the space is what a BIM user filters them by.
  void spatial_structure() {
    const int64_t site_place = w_.add(FMT_COMPILE("IFCLOCALPLACEMENT($,{})"), ref(world_));
    const int64_t site = w_.add(FMT_COMPILE("IFCSITE({},'Site',$,$,{},$,$,.ELEMENT.,$,$,$,$,$)"),
                                root("site"), ref(site_place));
    w_.add(FMT_COMPILE("IFCRELAGGREGATES({},$,$,{},({}))"), root("project-site"), ref(project_),
           ref(site));
    if (ground_works()) {
      const int64_t space_place =
          w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(site_place), ref(world_));
      const int64_t space =
          w_.add(FMT_COMPILE("IFCSPACE({},'External works',$,$,{},$,{},.ELEMENT.,.EXTERNAL.,0.)"),
                 root("space"), ref(space_place), text("Ground works"));
      w_.add(FMT_COMPILE("IFCRELAGGREGATES({},$,$,{},({}))"), root("site-space"), ref(site),
             ref(space));
      container_ = space, container_place_ = space_place;
      return;
    }
    const int64_t building_place =
        w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(site_place), ref(world_));
    const int64_t building =
        w_.add(FMT_COMPILE("IFCBUILDING({},'Building',$,$,{},$,$,.ELEMENT.,$,$,$)"),
               root("building"), ref(building_place));
    w_.add(FMT_COMPILE("IFCRELAGGREGATES({},$,$,{},({}))"), root("site-building"), ref(site),
           ref(building));
    // A building of storeys (layout.drawing's floor to floor): what it holds stands in the
    // lowest, its walls running up through the others.
    std::vector<int64_t> storeys;
    std::vector<double> levels{0};
    if (l_.envelope) levels = storey_levels(l_.drawing.storey, l_.drawing.storeys, l_.height);
    while (levels.size() > 1 && levels.back() >= l_.height - 1e-9) levels.pop_back();  // the top
    for (size_t k = 0; k < levels.size(); ++k) {
      const double at = levels[k];
      const int64_t place = w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(building_place),
                                   ref(k ? g_.axes({0, 0, at}, {0, 0, 1}, {1, 0, 0}) : world_));
      storeys.push_back(w_.add(FMT_COMPILE("IFCBUILDINGSTOREY({},{},$,$,{},$,$,.ELEMENT.,{})"),
                               root(k ? "storey " + std::to_string(k) : "storey"),
                               text("Level " + std::to_string(k)), ref(place), real(at)));
      if (k == 0) container_ = storeys.back(), container_place_ = place;
    }
    storeys_ = storeys, levels_ = levels;
    upper_.assign(storeys.size(), {});
    w_.add(FMT_COMPILE("IFCRELAGGREGATES({},$,$,{},{})"), root("building-storey"), ref(building),
           step_refs(storeys));
  }

  bool ground_works() const {
    return !l_.kind->upright() && l_.kind->ground() != Ground::sheet &&
           l_.kind->depiction() != Depiction::views;
  }

  // A product's placement: at its own corner (x, y in the surface's plane), relative to its
  // spatial container, as Revit and ArchiCAD expect; its profiles are drawn from that corner.
  int64_t placement_at(double x, double y) {
    g_.set_local_origin(x, y);
    const int64_t frame =
        l_.kind->upright()
            ? w_.add(FMT_COMPILE("IFCAXIS2PLACEMENT3D({},{},{})"), ref(g_.point(x, 0, y)),
                     ref(out_of_wall_), ref(along_))
            : w_.add(FMT_COMPILE("IFCAXIS2PLACEMENT3D({},$,$)"), ref(g_.point(x, y, 0)));
    return w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(container_place_), ref(frame));
  }
  // An opening's placement: at its own corner, relative to the sheet it voids (whose frame is
  // already the surface's plane), as IFC places openings in their host.
  int64_t placement_in_sheet(double x, double y, size_t sheet) {
    g_.set_local_origin(x, y);
    const Rect& s = l_.sheets()[sheet].area;
    const int64_t frame =
        w_.add(FMT_COMPILE("IFCAXIS2PLACEMENT3D({},$,$)"), ref(g_.point(x - s.x, y - s.y, 0)));
    return w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"), ref(sheet_places_[sheet]), ref(frame));
  }

  // The element's body as laid: one solid, whatever its shape (an L-shaped cut piece is one
  // profile, a piece in two parts one composite profile); a tree is a trunk and a canopy.
  // `parts`: piece_outlines(e), worked out once by the caller (a cut piece's is a union).
  std::vector<int64_t> solids(const Element& e, const std::vector<Outline>& parts,
                              const Rgb& colour) {
    const double t = l_.thickness;
    if (e.form == ElementForm::block) {
      const double w = l_.module_w, d = l_.module_h, h = l_.level_height;
      const Rect plan{static_cast<double>(e.cell_x - l_.view.origin[0]) * w,
                      static_cast<double>(e.cell_y - l_.view.origin[1]) * d, w, d};
      return {g_.solid(g_.rectangle(plan), static_cast<double>(e.cell_z - l_.view.origin[2]) * h, h,
                       colour)};
    }
    if (e.circle) {  // a tree: a trunk of 200 mm to 2.2 m, then its canopy as a drum
      const int64_t trunk = g_.solid(g_.circle(Circle{e.circle->cx, e.circle->cy, kTrunkWidth}), t,
                                     kTrunkHeight, Rgb{92, 64, 44});
      return {trunk, g_.solid(g_.circle(*e.circle), t + kTrunkHeight, e.circle->d, colour)};
    }
    const double base = e.stands ? t : 0, depth = e.stands ? kStandingHeight : t;
    const int64_t profile = parts.empty() ? g_.rectangle(laid_bounds(e)) : g_.profile(parts);
    return {g_.solid(profile, base, depth, colour)};
  }

  // An opening's outline, as an 'Annotation' curve in the sheet's plane: its hole is in the
  // sheet's body already, so no reader has anything to subtract (a screen has thousands).
  int64_t opening_shape(const Element& e) {
    std::vector<int64_t> curves;
    for (const Ring& ring : opening_rings(e, l_.chord_tolerance))
      curves.push_back(g_.shared_polyline(ring));
    const int64_t rep = w_.add(FMT_COMPILE("IFCSHAPEREPRESENTATION({},'Annotation','Curve2D',{})"),
                               ref(hole_context_), step_refs(curves));
    return w_.add(FMT_COMPILE("IFCPRODUCTDEFINITIONSHAPE($,$,({}))"), ref(rep));
  }

  // The fabrication sheets a perforated surface is cut into: each a plate whose body has its
  // openings as voids in its profile (one solid a reader meshes in a moment, as punched), each
  // opening an annotation assigned to it, with its data (element()).
  void sheets() {
    const double t = l_.thickness;
    const Rgb metal{201, 205, 210};
    const int64_t material =
        w_.add(FMT_COMPILE("IFCMATERIAL({},$,'metal')"), text(fmt::format("sheet, {:g} mm", t)));
    const bool framed = l_.envelope.has_value();  // its bodies are screen_sheets_'
    const std::vector<std::vector<Outline>> punched =
        framed ? std::vector<std::vector<Outline>>{} : punched_sheets(l_);
    for (size_t k = 0; k < l_.sheets().size(); ++k) {
      const FabricationSheet& s = l_.sheets()[k];
      const int64_t where = framed ? w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"),
                                            ref(container_place_), ref(world_))
                                   : placement_at(s.area.x, s.area.y);
      const int64_t body = framed ? screen_sheets_.body(k, metal)
                                  : g_.body({g_.solid(g_.profile(punched[k]), 0, t, metal)});
      const int64_t plate =
          w_.add(FMT_COMPILE("IFCPLATE({},{},$,'perforated sheet',{},{},{},.SHEET.)"),
                 root("sheet " + s.id), text(s.id), ref(where), ref(body), text(s.id));
      contained_.push_back(plate);
      sheet_plates_.push_back(plate);
      sheet_places_.push_back(where);
      const double net = s.surface * (1 - s.open_area) / 1e6;
      sets(plate, "sheet " + s.id, "IFCPLATE",
           {s.id, true, true, t, s.area.w, s.area.h, s.surface / 1e6, net});
    }
    w_.add(FMT_COMPILE("IFCRELASSOCIATESMATERIAL({},$,$,{},{})"), root("sheet-material"),
           step_refs(sheet_plates_), ref(material));
  }
  // An opening of a screen on a building: at its box's corner on the face, its profile in the
  // plane of the chord across it, relative to the sheet (placed at the building's origin).
  int64_t placement_in_framed_sheet(const Element& e) {
    const Rect b = laid_bounds(e);
    g_.set_local_origin(b.x, b.y);
    const FramedPose pose = opening_pose(l_, e);
    const auto& [dx, dy] = pose.along;
    return w_.add(FMT_COMPILE("IFCLOCALPLACEMENT({},{})"),
                  ref(sheet_places_[static_cast<size_t>(e.sheet)]),
                  ref(g_.axes(pose.origin, {dy, -dx, 0}, {dx, dy, 0})));
  }

  bool has_arc_contours() const {
    return !l_.outline_contour.empty() ||
           std::any_of(l_.zones.begin(), l_.zones.end(),
                       [](const ZoneCount& z) { return !z.contour.empty(); });
  }
  // The outline and zones whose edges are arcs, as annotations a setter-out or a coordinator
  // reads them by: their curves in the surface's plane, arcs kept.
  void arc_annotations() {
    if (!has_arc_contours()) return;
    auto annotate = [&](const std::string& name, const Contour& c) {
      const int64_t rep =
          w_.add(FMT_COMPILE("IFCSHAPEREPRESENTATION({},'Annotation','Curve2D',({}))"),
                 ref(annotation_), ref(g_.contour_curve(c)));
      const int64_t shape = w_.add(FMT_COMPILE("IFCPRODUCTDEFINITIONSHAPE($,$,({}))"), ref(rep));
      contained_.push_back(w_.add(FMT_COMPILE("IFCANNOTATION({},{},$,'setting out',{},{})"),
                                  root("annotation " + name), text(name), ref(placement_at(0, 0)),
                                  ref(shape)));
    };
    if (!l_.outline_contour.empty()) annotate("Outline", l_.outline_contour);
    for (const ZoneCount& z : l_.zones)
      if (!z.contour.empty()) annotate("Zone " + z.name, z.contour);
  }
  void element(const Element& e, size_t index) {
    const IfcClass c = class_of(l_, e);
    const Rect b = laid_bounds(e);
    const bool opening = e.form == ElementForm::opening;
    const bool framed = l_.envelope.has_value() && !opening;  // a unit of a building's wall
    const IfcEnvelopeWriter::Placed unit =
        framed ? envelope_.unit(e, container_place_, piece_colour(l_, e))
               : IfcEnvelopeWriter::Placed{};
    const int64_t where = framed                                   ? unit.placement
                          : opening && e.sheet >= 0 && l_.envelope ? placement_in_framed_sheet(e)
                          : opening && e.sheet >= 0
                              ? placement_in_sheet(b.x, b.y, static_cast<size_t>(e.sheet))
                              : placement_at(b.x, b.y);
    const std::vector<Outline> parts = opening ? std::vector<Outline>{} : piece_outlines(e);
    const int64_t product_shape = framed    ? unit.shape
                                  : opening ? opening_shape(e)
                                            : g_.body(solids(e, parts, piece_colour(l_, e)));
    // An opening is no IfcOpeningElement: one voiding a sheet whose body has the hole already
    // has every reader run a Boolean operation for nothing (web-ifc gives up on a sheet with
    // more than 150 and says so). It annotates its sheet, whose body is the sheet as punched.
    const int64_t id =
        opening ? w_.add(FMT_COMPILE("IFCANNOTATION({},{},$,{},{},{})"), root(e.id), text(e.id),
                         text(element_type_of(l_, e)), ref(where), ref(product_shape))
                : w_.add(FMT_COMPILE("{}({},{},$,{},{},{},{},{})"), c.entity, root(e.id),
                         text(e.id), text(element_type_of(l_, e)), ref(where), ref(product_shape),
                         text(e.id), c.predefined);
    if (opening && e.sheet >= 0) holes_[static_cast<size_t>(e.sheet)].push_back(id);
    if (framed)
      parts_[envelope_.facade_of(e)].push_back(id);  // nested in its façade's wall, only
    else
      contained_.push_back(id);
    const std::string& material = piece_material(l_, e);
    materials_[material].push_back(id);
    if (c.typed) {
      CoveringType& covering = types_[{material, stock_size_of(l_, e)}];
      covering.stock = {e.stock_w, e.stock_h};  // one stock size per type: the same for every piece
      covering.elements.push_back(id);
    }
    properties(e, index, id);
    quantities(e, id);
    const bool known = l_.kind->outdoors();
    sets(id, e.id, c.entity,
         {e.id, known, known, body_height(l_, e), b.w, b.h, gross_area(e, parts) / 1e6,
          e.area() / 1e6, body_volume(e)});
  }
  // The piece's area without what is cut away inside it (its outer rings).
  static double gross_area(const Element& e, const std::vector<Outline>& parts) {
    if (parts.empty()) return e.area();
    double area = 0;
    for (const Outline& part : parts) area += std::abs(signed_area(part.rings.front()));
    return area;
  }

  // IFC4's standard property and quantity sets for an element of class `entity`.
  void sets(int64_t id, const std::string& key, std::string_view entity, const IfcMeasures& m) {
    for (const IfcSet& set : standard_sets(entity, m)) {
      std::vector<int64_t> entries;
      for (const IfcSetEntry& entry : set.entries) entries.push_back(set_entry(entry));
      const bool quantities = set.name.rfind("Qto_", 0) == 0;
      const int64_t definition =
          quantities ? w_.add(FMT_COMPILE("IFCELEMENTQUANTITY({},{},$,$,{})"), root(set.name, key),
                              text(set.name), step_refs(entries))
                     : w_.add(FMT_COMPILE("IFCPROPERTYSET({},{},$,{})"), root(set.name, key),
                              text(set.name), step_refs(entries));
      w_.add(FMT_COMPILE("IFCRELDEFINESBYPROPERTIES({},$,$,({}),{})"),
             root(set.name + "-rel ", key), ref(id), ref(definition));
    }
  }
  int64_t set_entry(const IfcSetEntry& entry) {
    using K = IfcSetEntry::Kind;
    switch (entry.kind) {
      case K::property:
        return property(entry.name, entry.value);
      case K::length:
        return shared(FMT_COMPILE("IFCQUANTITYLENGTH({},$,$,{},$)"), text(entry.name),
                      real(entry.amount));
      case K::area:
        return shared(FMT_COMPILE("IFCQUANTITYAREA({},$,$,{},$)"), text(entry.name),
                      real(entry.amount));
      case K::volume:
        break;
    }
    return shared(FMT_COMPILE("IFCQUANTITYVOLUME({},$,$,{},$)"), text(entry.name),
                  real(entry.amount));
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
    const int64_t set = w_.add(FMT_COMPILE("IFCPROPERTYSET({},'Curdle_Element',$,{})"),
                               root("pset ", e.id), step_refs(props));
    w_.add(FMT_COMPILE("IFCRELDEFINESBYPROPERTIES({},$,$,({}),{})"), root("pset-rel ", e.id),
           ref(id), ref(set));
  }

  // curdle's own quantities: the piece's extent, thickness and area as the schedule gives them.
  void quantities(const Element& e, int64_t id) {
    const Rect b = laid_bounds(e);
    const bool standing = e.circle || e.stands;  // a tree, a bench: how tall, not how thick
    std::vector<int64_t> q{
        shared(FMT_COMPILE("IFCQUANTITYLENGTH('Length',$,$,{},$)"), real(b.w)),
        shared(FMT_COMPILE("IFCQUANTITYLENGTH('Width',$,$,{},$)"), real(b.h)),
        standing
            ? shared(FMT_COMPILE("IFCQUANTITYLENGTH('Height',$,$,{},$)"), real(body_height(l_, e)))
            : shared(FMT_COMPILE("IFCQUANTITYLENGTH('Thickness',$,$,{},$)"),
                     real(body_height(l_, e))),
        shared(FMT_COMPILE("IFCQUANTITYAREA('NetArea',$,$,{},$)"), real(e.area() / 1e6))};
    const int64_t set = w_.add(FMT_COMPILE("IFCELEMENTQUANTITY({},'Curdle_Quantities',$,$,{})"),
                               root("qto ", e.id), step_refs(q));
    w_.add(FMT_COMPILE("IFCRELDEFINESBYPROPERTIES({},$,$,({}),{})"), root("qto-rel ", e.id),
           ref(id), ref(set));
  }

  // What the storey whose floor is at or below `base` (mm above the building's base) contains:
  // a window with its sill on the upper floor stands in the upper storey.
  std::vector<int64_t>& contained_in(double base) {
    size_t k = 0;
    while (k + 1 < levels_.size() && levels_[k + 1] <= base + 1e-6) ++k;
    return k == 0 ? contained_ : upper_[k];
  }

  // What groups elements: containment in each storey, each sheet's holes, materials and
  // covering types.
  void closing_relations() {
    if (!contained_.empty())
      w_.add(FMT_COMPILE("IFCRELCONTAINEDINSPATIALSTRUCTURE({},$,$,{},{})"), root("contained"),
             step_refs(contained_), ref(container_));
    for (size_t k = 1; k < upper_.size(); ++k)
      if (!upper_[k].empty())
        w_.add(FMT_COMPILE("IFCRELCONTAINEDINSPATIALSTRUCTURE({},$,$,{},{})"),
               root("contained " + std::to_string(k)), step_refs(upper_[k]), ref(storeys_[k]));
    for (size_t k = 0; k < holes_.size(); ++k)
      if (!holes_[k].empty())
        w_.add(FMT_COMPILE("IFCRELASSIGNSTOPRODUCT({},'holes',$,{},$,{})"),
               root("holes " + l_.sheets()[k].id), step_refs(holes_[k]), ref(sheet_plates_[k]));
    for (const auto& [name, ids] : materials_) {
      const int64_t m = w_.add(FMT_COMPILE("IFCMATERIAL({},$,$)"), text(name));
      w_.add(FMT_COMPILE("IFCRELASSOCIATESMATERIAL({},$,$,{},{})"), root("material " + name),
             step_refs(ids), ref(m));
    }
    const char* predefined = l_.kind->upright() ? ".CLADDING." : ".FLOORING.";
    for (const auto& [key, covering] : types_) {
      const auto& [material, size] = key;
      std::vector<int64_t> sets;
      if (covering.stock[0] > 0) {
        const std::vector<int64_t> tiling{length("TileLength", covering.stock[0]),
                                          length("TileWidth", covering.stock[1])};
        sets.push_back(w_.add(FMT_COMPILE("IFCPROPERTYSET({},'Curdle_Tiling',$,{})"),
                              root("tiling " + material + size), step_refs(tiling)));
      }
      const std::string name = material + ", " + size;
      const int64_t type = w_.add(
          FMT_COMPILE("IFCCOVERINGTYPE({},{},$,$,{},$,$,{},{})"), root("type " + name), text(name),
          sets.empty() ? "$" : step_refs(sets), text(l_.element_type), predefined);
      w_.add(FMT_COMPILE("IFCRELDEFINESBYTYPE({},$,$,{},{})"), root("type-rel " + name),
             step_refs(covering.elements), ref(type));
    }
  }

  // The pieces of one material and stock size, and that size.
  struct CoveringType {
    std::array<double, 2> stock{0, 0};
    std::vector<int64_t> elements;
  };

  StepWriter w_;
  IfcGeometryWriter g_;
  const Layout& l_;
  IfcEnvelopeWriter envelope_;
  std::vector<std::vector<int64_t>> parts_ = std::vector<std::vector<int64_t>>(l_.frames().size());
  IfcGuidSource guids_;
  fmt::memory_buffer scratch_;  // a shared entity's text, reused
  int64_t owner_ = 0, world_ = 0, out_of_wall_ = 0, along_ = 0, annotation_ = 0;
  int64_t hole_context_ = 0, project_ = 0, container_ = 0, container_place_ = 0;
  std::vector<int64_t> contained_, sheet_plates_, sheet_places_;
  std::vector<std::vector<int64_t>> holes_ =  // each sheet's openings
      std::vector<std::vector<int64_t>>(l_.sheets().size());
  IfcScreenSheets screen_sheets_{g_, l_};    // a screen on a building: its sheets' bodies
  std::vector<int64_t> storeys_;             // Level 0, 1, ...
  std::vector<double> levels_{0};            // their floors, mm above the base
  std::vector<std::vector<int64_t>> upper_;  // what each storey above Level 0 contains
  std::map<std::string, std::vector<int64_t>> materials_;
  struct TextHash {  // looks a shared entity up by its text, without making a string of it
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  std::unordered_map<std::string, int64_t, TextHash, std::equal_to<>> shared_;
  std::map<std::pair<std::string, std::string>, CoveringType> types_;
};

}  // namespace

void write_layout_ifc(std::ostream& out, const Layout& layout) { IfcModel(out, layout).write(); }

}  // namespace curdle
