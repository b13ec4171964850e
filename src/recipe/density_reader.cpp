// [curds.density]: kind = "linear" (from, to, values), "radial" (centre, radius, values) or
// "image" (path, values, optional rect); coordinates in mm on a layout, in cells otherwise.
#include "recipe/density_reader.h"

#include <cmath>

#include "layout/cell_placement.h"

namespace curdle::reading {
namespace {

constexpr double kMostValue = 1000;  // g multiplies P_K: beyond this every cell is certain anyway
constexpr double kMostCoordinate = 1e13;

std::string point_form(int dimension) {
  return dimension == 1 ? "[x]" : dimension == 2 ? "[x, y]" : "[x, y, z]";
}

std::array<double, 3> read_point(TableReader& r, const std::string& key, int dimension,
                                 const std::string& units) {
  const toml::node* n = r.get(key);
  if (!n) r.fail(key, "is required: a point " + point_form(dimension) + " in " + units);
  const toml::array* a = n->as_array();
  std::array<double, 3> p{0, 0, 0};
  bool ok = a && a->size() == static_cast<size_t>(dimension);
  for (int d = 0; ok && d < dimension; ++d) {
    const auto x = finite_number(a->get(static_cast<size_t>(d)));
    ok = x && std::abs(*x) <= kMostCoordinate;
    if (ok) p[d] = *x;
  }
  if (!ok)
    r.fail(key, "must be a point " + point_form(dimension) + " in " + units +
                    ": finite numbers, at most 10^13 in size");
  return p;
}

std::array<double, 2> read_values(TableReader& r, const std::string& meaning) {
  const toml::node* n = r.get("values");
  const std::string allowed = "must be two numbers [" + meaning +
                              "], each from 0 to 1000: the factor g on the curd's final "
                              "survival P_K (1 leaves it as it is)";
  if (!n) r.fail("values", "is required; it " + allowed);
  const toml::array* a = n->as_array();
  std::array<double, 2> v{};
  bool ok = a && a->size() == 2;
  for (size_t i = 0; ok && i < 2; ++i) {
    const auto x = finite_number(a->get(i));
    ok = x && *x >= 0 && *x <= kMostValue;
    if (ok) v[i] = *x;
  }
  if (!ok) r.fail("values", allowed);
  return v;
}

}  // namespace

DensityField read_density(TableReader& curd, const std::string& path, const Lattice& lattice,
                          const std::string& units) {
  const toml::table* t = curd.get("density")->as_table();
  if (!t) curd.fail("density", "must be a table, written [curds.density] after its [[curds]]");
  TableReader r(*t, path + ".density", curd.source(),
                {"kind", "values", "from", "to", "centre", "radius", "path", "rect"});
  if (lattice.mode != Mode::canonical)
    r.fail("kind",
           "a density field needs lattice.mode = \"canonical\": exact and quota modes fix how "
           "many cells survive, which a field cannot vary");
  DensityField f;
  f.dimension = lattice.dimension;
  const auto kind = read_string(r, "kind", "\"linear\", \"radial\" or \"image\"");
  if (!kind) r.fail("kind", "is required: \"linear\", \"radial\" or \"image\"");
  auto refuse = [&](std::initializer_list<const char*> keys, const std::string& belongs) {
    for (const char* key : keys)
      if (r.get(key)) r.fail(key, "belongs to " + belongs + ", not to kind \"" + *kind + "\"");
  };
  if (*kind == "linear") {
    f.kind = DensityKind::linear;
    refuse({"centre", "radius"}, "kind \"radial\"");
    refuse({"path", "rect"}, "kind \"image\"");
    f.from = read_point(r, "from", f.dimension, units);
    f.to = read_point(r, "to", f.dimension, units);
    if (f.from == f.to)
      r.fail("to", "must differ from `from`: the field runs from one to the other");
    f.values = read_values(r, "at from, at to");
  } else if (*kind == "radial") {
    f.kind = DensityKind::radial;
    refuse({"from", "to"}, "kind \"linear\"");
    refuse({"path", "rect"}, "kind \"image\"");
    f.centre = read_point(r, "centre", f.dimension, units);
    const toml::node* radius = r.get("radius");
    const auto x = finite_number(radius);
    if (!x || *x <= 0 || *x > kMostCoordinate)
      r.fail("radius", std::string(radius ? "must be" : "is required:") +
                           " a distance above 0 in " + units + ", at most 10^13");
    f.radius = *x;
    f.values = read_values(r, "at the centre, at the radius and beyond");
  } else if (*kind == "image") {
    f.kind = DensityKind::image;
    refuse({"from", "to"}, "kind \"linear\"");
    refuse({"centre", "radius"}, "kind \"radial\"");
    if (f.dimension != 2)
      r.fail("kind", "an image field needs a 2-D lattice, not " + std::to_string(f.dimension) +
                         "-D; use \"linear\" or \"radial\"");
    const auto image = read_string(r, "path", "a file name");
    if (!image || image->empty())
      r.fail("path", "is required: a greyscale image, relative to the recipe");
    f.path = *image;
    if (const toml::node* n = r.get("rect")) {
      const toml::array* a = n->as_array();
      bool ok = a && a->size() == 4;
      for (size_t i = 0; ok && i < 4; ++i) {
        const auto x = finite_number(a->get(i));
        ok = x && std::abs(*x) <= kMostCoordinate && (i < 2 || *x > 0);
        if (ok) f.rect[i] = *x;
      }
      if (!ok) r.fail("rect", "must be [x, y, width, height] in " + units + ", sizes above 0");
      f.rect_given = true;
    }
    f.values = read_values(r, "black, white");
  } else {
    r.fail("kind", "must be \"linear\", \"radial\" or \"image\", not \"" + *kind + "\"");
  }
  return f;
}

void place_density(DensityField& field, const std::optional<LayoutSpec>& layout, const Box& view,
                   const Box& whole_field) {
  const bool on_surface = layout && layout->kind->dimension() != 1;
  field.placement = on_surface ? cell_placement(*layout, view) : CellPlacement{};
  if (field.kind == DensityKind::image && !field.rect_given) {
    if (on_surface) {  // the picture covers the surface
      const auto extent = surface_extent(*layout, view);
      field.rect = {0, 0, extent[0], extent[1]};
    } else {  // or the field's cells
      field.rect = {0, 0, static_cast<double>(whole_field.size[0]),
                    static_cast<double>(whole_field.size[1])};
    }
  }
}

std::string density_units(const TableReader& top) {
  const toml::node* layout = top.get("layout");
  const toml::table* t = layout ? layout->as_table() : nullptr;
  const toml::node* kind = t ? t->get("kind") : nullptr;
  if (!t || (kind && kind->value<std::string>() == "rhythm")) return "cells";
  return "millimetres";
}

}  // namespace curdle::reading
