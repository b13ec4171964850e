// The Python module's native part, curdle._curdle: the application layer as Python calls it.
// curdle/__init__.py gives it its Python shape (Recipe, dict overrides, structured arrays); here
// every call goes through the same functions as the command line, so that bytes are the same.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>

#include "app/fit_run.h"
#include "app/generated_run.h"
#include "app/measure_run.h"
#include "app/search_run.h"
#include "app/version.h"
#include "curdle/error.h"
#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "export/report/measure_files.h"
#include "layout/piece_rows.h"
#include "layout/wkt.h"
#include "python/interruptible.h"
#include "recipe/toml_reader.h"

namespace py = pybind11;

namespace curdle::python {
namespace {

using Generated = std::shared_ptr<const app::GeneratedRun>;

// How Python spells the run parameters that messages name.
std::string python_name(const std::string& parameter) {
  if (parameter == "set") return "overrides";
  return parameter;
}

struct RunArguments {
  std::string text, path;
  std::vector<std::string> overrides;
  std::string seed, window;
  uint64_t max_memory = 0;
};

app::RunRequest run_request(const RunArguments& a) {
  return {.recipe_text = a.text,
          .recipe_path = a.path,
          .overrides = a.overrides,
          .seed = a.seed,
          .window = a.window,
          .max_memory = a.max_memory,
          .memory_limit_hint = "pass max_memory (bytes) to generate"};
}

Generated generate(const RunArguments& a, bool with_layout, int threads) {
  app::Run run = app::resolve_run(run_request(a));
  return run_interruptible([&](InterruptWatch&) {
    return std::make_shared<const app::GeneratedRun>(
        app::generate_run(std::move(run), with_layout, threads, nullptr));
  });
}

// The values of the run's view as an array owned by its capsule (no copy): [x] on a line,
// [y, x] on a plane, [z, y, x] in space, from the view's corner.
py::array_t<uint16_t> values_array(const app::GeneratedRun& g) {
  auto values = std::make_unique<std::vector<uint16_t>>(values_in(g.field, g.run.view));
  const Box& v = g.run.view;
  std::vector<py::ssize_t> shape;
  for (int axis = g.run.recipe.design.lattice.dimension - 1; axis >= 0; --axis)
    shape.push_back(static_cast<py::ssize_t>(v.size[static_cast<size_t>(axis)]));
  uint16_t* data = values->data();
  py::capsule owner(values.release(),
                    [](void* p) { delete static_cast<std::vector<uint16_t>*>(p); });
  return py::array_t<uint16_t>(shape, data, owner);
}

std::vector<int64_t> view_origin(const app::GeneratedRun& g) {
  const int e = g.run.recipe.design.lattice.dimension;
  return {g.run.view.origin.begin(), g.run.view.origin.begin() + e};
}

const Layout& layout_of(const app::GeneratedRun& g) {
  if (!g.layout) throw InputError(parameter("layout"), "this run has no layout");
  return *g.layout;
}

// A piece's outline as rings of (x, y) points in mm, outer ring first.
py::list outline_rings(const std::vector<Outline>& outlines) {
  py::list parts;
  for (const Outline& o : outlines) {
    py::list rings;
    for (const Ring& ring : o.rings) {
      py::list points;
      for (const auto& p : ring) points.append(py::make_tuple(p[0], p[1]));
      rings.append(points);
    }
    parts.append(rings);
  }
  return parts;
}

// Every row of schedule.csv as columns: numbers as arrays (NaN where the CSV is empty), words
// as lists; __init__.py makes a structured array of them.
py::dict schedule_columns(const app::GeneratedRun& g) {
  const Layout& layout = layout_of(g);
  const size_t n = layout.elements.size();
  const char* numbers[] = {"level",
                           "x_mm",
                           "y_mm",
                           "z_mm",
                           "width_mm",
                           "height_mm",
                           "depth_mm",
                           "area_m2",
                           "stock_width_mm",
                           "stock_height_mm",
                           "opening_x_mm",
                           "opening_y_mm",
                           "opening_diameter_mm",
                           "strip_x_mm",
                           "strip_y_mm"};
  std::map<std::string, py::array_t<double>> number;
  for (const char* name : numbers) number.emplace(name, py::array_t<double>(n));
  py::array_t<int64_t> row(n), column(n);
  py::array_t<uint32_t> value(n);
  py::array_t<bool> cut(n);
  py::list id, lot, type, colour, material, wkt, facade;
  const double none = std::numeric_limits<double>::quiet_NaN();
  auto put = [&](const char* name, size_t i, std::optional<double> v) {
    number.at(name).mutable_at(i) = v.value_or(none);
  };
  for (size_t i = 0; i < n; ++i) {
    const ScheduleRow r = schedule_row(layout, i);
    put("level", i, r.level ? std::optional<double>(static_cast<double>(*r.level)) : std::nullopt);
    row.mutable_at(i) = r.row;
    column.mutable_at(i) = r.column;
    put("x_mm", i, r.x);
    put("y_mm", i, r.y);
    put("z_mm", i, r.z);
    put("width_mm", i, r.width);
    put("height_mm", i, r.height);
    put("depth_mm", i, r.depth);
    put("area_m2", i, area_m2(r.area));
    put("stock_width_mm", i, r.stock_width);
    put("stock_height_mm", i, r.stock_height);
    put("opening_x_mm", i, r.opening_x);
    put("opening_y_mm", i, r.opening_y);
    put("opening_diameter_mm", i, r.opening_diameter);
    put("strip_x_mm", i, r.strip_x);  // a building's: on its unrolled strip
    put("strip_y_mm", i, r.strip_y);
    facade.append(r.facade);
    value.mutable_at(i) = r.value;
    cut.mutable_at(i) = r.cut;
    id.append(r.id);
    lot.append(r.lot);
    type.append(r.element_type);
    colour.append(r.colour);
    material.append(r.material);
    wkt.append(outlines_wkt(r.outlines));
  }
  py::dict columns;
  columns["element_id"] = id;
  columns["lot"] = lot;
  columns["level"] = number.at("level");
  columns["row"] = row;
  columns["column"] = column;
  for (const char* name : numbers)
    if (std::string(name) != "level") columns[name] = number.at(name);
  columns["value"] = value;
  columns["element_type"] = type;
  columns["colour"] = colour;
  columns["material"] = material;
  columns["cut"] = cut;
  columns["shape_wkt"] = wkt;
  columns["facade"] = facade;  // a building's façade ("S", "E2"); empty elsewhere
  return columns;
}

py::dict layout_facts(const app::GeneratedRun& g) {
  const Layout& l = layout_of(g);
  py::dict facts;
  facts["kind"] = std::string(l.kind->name());
  facts["element_type"] = l.element_type;
  facts["width_mm"] = l.width;
  facts["height_mm"] = l.height;
  facts["thickness_mm"] = l.thickness;
  facts["upright"] = l.kind->upright();  // a wall: y runs up, thickness into the wall
  facts["dimension"] = l.kind->dimension();
  facts["level_height_mm"] = l.level_height;
  facts["columns"] = l.columns;
  facts["rows"] = l.rows;
  facts["elements"] = l.elements.size();
  facts["omitted"] = l.omitted;
  facts["sheets"] = l.sheets().size();
  facts["notes"] = l.notes;
  facts["violations"] = l.violations;
  py::list legend;
  for (const LegendEntry& e : l.legend) {
    py::dict entry;
    entry["value"] = e.value;
    entry["label"] = e.label;
    entry["colour"] = hex_colour(e.colour);
    entry["count"] = e.count;
    legend.append(entry);
  }
  facts["legend"] = legend;
  return facts;
}

// Writes the outputs named (none: the defaults) into `dir`, replaced whole or not at all as
// `curdle generate --out` does; returns the files written and the defaults left out for size.
struct Skipped : app::RunObserver {
  std::vector<std::string> notes;
  std::unique_ptr<app::ProgressTask> begin(const std::string&) override { return nullptr; }
  void skipped(const std::string& output, uint64_t count, const std::string& unit,
               uint64_t limit) override {
    notes.push_back(output + " left out: " + std::to_string(count) + " " + unit + ", above " +
                    std::to_string(limit) + "; name it in outputs to write it");
  }
  void not_installed(const std::string& output, const std::string& why) override {
    notes.push_back(output + " left out: " + why);
  }
};

// The run a native call was given: None (a Run made by hand, or an unbound method called
// with None) is a TypeError, never a null run read.
const app::GeneratedRun& generated(const Generated& g) {
  if (!g) throw py::type_error("expected a generated run (from Recipe.generate()), got None");
  return *g;
}

py::tuple write_outputs(const Generated& g, const std::vector<std::string>& named,
                        const std::filesystem::path& dir) {
  generated(g);
  Skipped observer;
  const auto outputs = app::select_outputs(g->run, named, &observer);
  const auto files = run_interruptible([&](InterruptWatch&) {
    app::StagingDirectory sink(dir, app::is_output_name);
    app::write_generated(*g, outputs, sink, nullptr);
    sink.commit();
    return sink.files();
  });
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.string());
  return py::make_tuple(names, observer.notes);
}

std::string search_json(const RunArguments& a, const std::string& seeds, const std::string& segment,
                        const std::vector<std::string>& targets, int top, int64_t stride,
                        int threads) {
  app::SearchRequest request{.run = run_request(a),
                             .seeds = seeds,
                             .segment = segment,
                             .targets = targets,
                             .stride = stride,
                             .top = top,
                             .threads = threads};
  const app::SearchRun s = app::resolve_search(request);
  return run_interruptible([&](InterruptWatch& watch) {
    return app::search_hits_json(s, app::run_search(s, {}, &watch.flag())).dump();
  });
}

std::string measure_json(const std::string& image, int values, std::optional<double> threshold,
                         int base, uint64_t max_memory) {
  const app::MeasureRequest request{.image = image,
                                    .values = values,
                                    .threshold = threshold,
                                    .base = base,
                                    .max_memory = max_memory};
  return run_interruptible(
      [&](InterruptWatch&) { return measure_to_json(app::run_measure(request)).dump(); });
}

py::dict fit_source(const std::string& source, int base, int stages, int curds, int cell_pixels,
                    uint64_t max_memory, int states, bool stage_wise, bool wheys) {
  const app::FitRequest request{.source = source,
                                .base = base,
                                .stages = stages,
                                .curds = curds,
                                .cell_pixels = cell_pixels,
                                .max_memory = max_memory,
                                .states = states,
                                .stage_wise = stage_wise,
                                .wheys = wheys};
  const app::FittedRecipe f =
      run_interruptible([&](InterruptWatch&) { return app::run_fit(request); });
  py::dict out;
  out["name"] = f.name;
  out["lattice"] =
      py::dict(py::arg("base") = f.lattice.base, py::arg("dimension") = f.lattice.dimension,
               py::arg("stages") = f.lattice.stages);
  out["cells"] = std::vector<int64_t>(f.size.begin(), f.size.begin() + f.lattice.dimension);
  py::list fitted;
  for (const app::FittedCurd& c : f.curds) {
    py::list stages_out;
    for (const StageFit& s : c.fit.stages)
      stages_out.append(py::dict(py::arg("stage") = s.stage, py::arg("probability") = s.probability,
                                 py::arg("low") = s.low, py::arg("high") = s.high,
                                 py::arg("measured") = s.measured, py::arg("expected") = s.expected,
                                 py::arg("expected_sd") = s.expected_sd, py::arg("z") = s.z,
                                 py::arg("p_value") = s.p_value));
    fitted.append(py::dict(py::arg("name") = c.name, py::arg("colour") = c.colour,
                           py::arg("stages") = stages_out, py::arg("chi_square") = c.fit.chi_square,
                           py::arg("degrees") = c.fit.degrees, py::arg("p_value") = c.fit.p_value));
  }
  out["curds"] = fitted;
  // The chain, when the cells were read as one (or compared with one): as the page gets it.
  out["chain"] = f.chain ? py::module_::import("json").attr("loads")(
                               app::chain_reading_json(*f.chain, f.lattice.stages).dump())
                         : py::object(py::none());
  out["recipe_is_chain"] = f.recipe_is_chain;
  out["warnings"] = f.warnings;
  out["pixels_per_cell"] = f.pixels_per_cell;
  out["toml"] = f.toml;
  return out;
}

// InputError becomes curdle.InputError (ResourceLimitError its subclass) with the message the
// command line prints and where it came from as attributes.
void register_errors(py::module_& m) {
  static py::exception<InputError> input(m, "InputError", PyExc_ValueError);
  static py::exception<ResourceLimitError> limit(m, "ResourceLimitError", input.ptr());
  static py::exception<WorkStopped> stopped(m, "WorkStopped", PyExc_RuntimeError);
  input.attr("__doc__") =
      "Bad input: a recipe key, a value, a file or a call's argument. The message names what "
      "is wrong and what is allowed; `file`, `line`, `column`, `key` and `parameter` say where.";
  limit.attr("__doc__") =
      "A run that would need more memory, cells or time than allowed (max_memory); the message "
      "says how much and how to ask for less.";
  stopped.attr("__doc__") = "A run stopped before it finished (Ctrl-C, or its caller gave up).";
  py::register_exception_translator([](std::exception_ptr p) {
    auto raise = [](const py::object& type, const InputError& e) {
      py::object error = type(render_error(e, python_name));
      const SourceLocation& w = e.where();
      error.attr("file") = w.file;
      error.attr("line") = w.line;
      error.attr("column") = w.column;
      error.attr("key") = w.key;
      error.attr("parameter") = python_name(w.parameter);
      PyErr_SetObject(type.ptr(), error.ptr());
    };
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ResourceLimitError& e) {
      raise(limit, e);
    } catch (const InputError& e) {
      raise(input, e);
    } catch (const WorkStopped& e) {
      stopped(e.what());
    }
  });
}

void bind_run(py::module_& m) {
  py::class_<app::GeneratedRun, std::shared_ptr<app::GeneratedRun>>(m, "GeneratedRun")
      .def_property_readonly("seed", [](const app::GeneratedRun& g) { return g.run.seed; })
      .def_property_readonly("name",
                             [](const app::GeneratedRun& g) { return g.run.recipe.design.name; })
      // One per [[curds]] table: its name, its first bit in a value, how many bits it takes,
      // and a Markov curd's states (dead first; empty for a plain curd).
      .def_property_readonly(
          "curd_bits",
          [](const app::GeneratedRun& g) {
            const auto& curds = g.run.recipe.design.curds;
            py::list out;
            for (const CurdGroup& c : curd_groups(curds)) {
              std::vector<std::string> states;
              if (c.chain)
                for (uint32_t s = 0; s <= c.chain->living(); ++s)
                  states.push_back(c.chain->state_name(s));
              out.append(py::make_tuple(curds[c.first].name, c.first, c.planes, states));
            }
            return out;
          })
      .def_property_readonly("origin", view_origin)
      .def_property_readonly("has_layout",
                             [](const app::GeneratedRun& g) { return g.layout.has_value(); })
      .def("values", values_array)
      .def("layout_facts", layout_facts)
      .def("schedule_columns", schedule_columns)
      .def(
          "element_outlines",
          [](const app::GeneratedRun& g, size_t i) {
            const Layout& l = layout_of(g);
            if (i >= l.elements.size()) throw py::index_error("no element " + std::to_string(i));
            return outline_rings(schedule_row(l, i).outlines);
          },
          py::arg("index"))
      .def(
          "output_bytes",
          [](const Generated& g, const std::string& name) {
            const app::GeneratedRun& run = generated(g);
            return py::bytes(
                run_interruptible([&](InterruptWatch&) { return app::output_bytes(run, name); }));
          },
          py::arg("name"));
}

}  // namespace
}  // namespace curdle::python

PYBIND11_MODULE(_curdle, m) {
  using namespace curdle;
  using namespace curdle::python;
  m.doc() = "curdle's native module; import curdle instead";
  remember_main_thread();
  register_errors(m);
  bind_run(m);
  m.def("version", &app::version);
  m.def("read_recipe", &app::read_recipe_file, py::arg("path"));
  // A recipe's text parsed as TOML, as generate parses it, so that broken TOML is refused where
  // the recipe is made; its keys are checked when it runs, after the overrides.
  m.def(
      "check_toml",
      [](const std::string& text, const std::string& path) {
        (void)reading::parse_toml(text, path);
      },
      py::arg("text"), py::arg("path"));
  m.def(
      "generate",
      [](const std::string& text, const std::string& path,
         const std::vector<std::string>& overrides, const std::string& seed,
         const std::string& window, bool layout, int threads, uint64_t max_memory) {
        return generate({text, path, overrides, seed, window, max_memory}, layout, threads);
      },
      py::arg("text"), py::arg("path"), py::arg("overrides"), py::arg("seed"), py::arg("window"),
      py::arg("layout"), py::arg("threads"), py::arg("max_memory"));
  m.def("write", write_outputs, py::arg("run"), py::arg("outputs"), py::arg("out"));
  m.def(
      "search",
      [](const std::string& text, const std::string& path,
         const std::vector<std::string>& overrides, const std::string& seeds,
         const std::string& segment, const std::vector<std::string>& targets, int top,
         int64_t stride, int threads, uint64_t max_memory) {
        return search_json({text, path, overrides, "", "", max_memory}, seeds, segment, targets,
                           top, stride, threads);
      },
      py::arg("text"), py::arg("path"), py::arg("overrides"), py::arg("seeds"), py::arg("segment"),
      py::arg("targets"), py::arg("top"), py::arg("stride"), py::arg("threads"),
      py::arg("max_memory"));
  m.def("measure", measure_json, py::arg("path"), py::arg("values"), py::arg("threshold"),
        py::arg("base"), py::arg("max_memory"));
  m.def("fit", fit_source, py::arg("source"), py::arg("base"), py::arg("stages"), py::arg("curds"),
        py::arg("cell_pixels"), py::arg("max_memory"), py::arg("states"), py::arg("stage_wise"),
        py::arg("wheys"));
  m.def("outputs", [] {
    py::list list;
    for (const app::Output& o : app::output_registry())
      list.append(
          py::dict(py::arg("name") = o.name, py::arg("description") = o.description,
                   py::arg("needs_layout") = o.needs_layout, py::arg("by_default") = o.by_default,
                   py::arg("for_site_drawing") = o.for_site_drawing,
                   py::arg("for_kind") = o.kind_owned ? py::object(py::str(app::owner_of(o)))
                                                      : py::object(py::none())));
    return list;
  });
}
