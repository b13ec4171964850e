#include "building/building.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "building/facades.h"
#include "curdle/error.h"
#include "layout/contour.h"
#include "layout/curved_facade.h"

namespace curdle {
namespace {

constexpr double kEps = 1e-6;
constexpr size_t kMostOpenings = 10000;  // as many as a recipe may list

// Keys are named relative to [layout.building]; its reader adds the recipe's location.
[[noreturn]] void refuse(const char* key, const std::string& what) {
  SourceLocation where;
  where.key = key;
  throw InputError(where, what);
}

// A height from the base in whole courses of `pitch`, or refused naming the nearest two.
int64_t whole_courses(double height, double pitch, const char* key = "height") {
  const double n = height / pitch;
  if (std::fabs(n - std::round(n)) * pitch < 0.01) return static_cast<int64_t>(std::round(n));
  const double lower = std::floor(n) * pitch, upper = std::ceil(n) * pitch;
  refuse(key, fmt::format("{:g} mm is not whole courses of {:g} mm (a unit and its bed "
                          "joint): {:g} mm ({} courses) or {:g} mm ({} courses) are",
                          height, pitch, lower, std::floor(n), upper, std::ceil(n)));
}

// y moved onto the nearest course line (a multiple of `pitch`).
double on_course(double y, double pitch) { return std::round(y / pitch) * pitch; }

// The openings a window rule places: each façade long enough, each storey.
std::vector<BuildingOpening> ruled_windows(const WindowRule& rule,
                                           const std::vector<SurfaceFrame>& facades,
                                           const BuildingKeys& keys) {
  std::vector<BuildingOpening> out;
  const double height = keys.height;
  const std::vector<double> levels = storey_levels(keys.storey, keys.storeys, height);
  for (const SurfaceFrame& f : facades) {
    const double room = f.length - 2 * rule.clear;
    if (room < rule.size[0]) continue;
    const int64_t n = static_cast<int64_t>(std::floor((room - rule.size[0]) / rule.every)) + 1;
    const double margin = (f.length - static_cast<double>(n - 1) * rule.every - rule.size[0]) / 2;
    const double top = f.height > 0 ? f.height : height;
    for (const double level : levels) {
      if (level + rule.sill + rule.size[1] > top + kEps) break;
      if (out.size() + static_cast<size_t>(n) > kMostOpenings)
        refuse("windows", fmt::format("would set more than {} windows: fewer, larger or further "
                                      "apart",
                                      kMostOpenings));
      for (int64_t k = 0; k < n; ++k)
        out.push_back({std::to_string(f.index),
                       Rect{margin + static_cast<double>(k) * rule.every, level + rule.sill,
                            rule.size[0], rule.size[1]},
                       "window"});
    }
  }
  return out;
}

// An opening with the name every output gives it.
struct NamedOpening {
  BuildingOpening opening;
  std::string name;
  bool gone = false;  // a rule's window omitted, or replaced by a listed opening
};

// The rule's window called `name` among `all` (from `first` on), or refused under `key`.
size_t ruled_window(std::vector<NamedOpening>& all, size_t first, const std::string& name,
                    const char* key) {
  for (size_t i = first; i < all.size(); ++i)
    if (all[i].name == name) {
      if (all[i].gone)
        refuse(key, fmt::format("names {} twice (omitted or replaced already)", name));
      return i;
    }
  refuse(key,
         fmt::format("names {}, which is not a window of the rule: it sets {}", name,
                     first < all.size() ? fmt::format("{} to {}", all[first].name, all.back().name)
                                        : std::string("none here")));
}

// Every opening with its name: the listed ones, then the rule's windows, numbered in that order,
// doors and windows apart ("D-1", "W-12"). Omitting or replacing a rule's window keeps the
// others' names, so that W-17 is the same window before and after a change of the recipe; a
// replacement of the same type takes the replaced one's name, a door in a window's place the
// next door's.
std::vector<NamedOpening> named_openings(const BuildingKeys& keys,
                                         const std::vector<SurfaceFrame>& facades) {
  std::vector<NamedOpening> all;
  size_t doors = 0, windows = 0;
  auto next = [&](const std::string& type) {
    return type == "door" ? fmt::format("D-{}", ++doors) : fmt::format("W-{}", ++windows);
  };
  for (const BuildingOpening& o : keys.openings)
    if (o.replaces.empty()) all.push_back({o, next(o.type)});
  const size_t first_ruled = all.size();
  if (keys.windows) {
    for (BuildingOpening& o : ruled_windows(*keys.windows, facades, keys))
      all.push_back({std::move(o), next("window")});
    for (const std::string& name : keys.windows->omit)
      all[ruled_window(all, first_ruled, name, "windows")].gone = true;
  }
  for (const BuildingOpening& o : keys.openings) {
    if (o.replaces.empty()) continue;
    const size_t i = ruled_window(all, first_ruled, o.replaces, "openings");
    NamedOpening in_place{o, o.type == "window" ? all[i].name : next(o.type)};
    if (in_place.opening.facade.empty()) in_place.opening.facade = all[i].opening.facade;
    all[i].gone = true;
    all.insert(all.begin() + static_cast<std::ptrdiff_t>(i) + 1, std::move(in_place));
  }
  std::erase_if(all, [](const NamedOpening& o) { return o.gone; });
  return all;
}

// The least a joint may close to at the back of a curved wall, mm.
constexpr double kNarrowestJoint = 3;

// A curved façade laid as straight units on chords of its arc: how far each sits inside the arc
// and how its joints taper from the face to the back, or refused where they would close.
std::string joint_taper(const SurfaceFrame& f, const LayoutSpec& spec, double depth, bool path) {
  const Arc arc = arc_between({f.from[0], f.from[1], f.bulge}, {f.to[0], f.to[1], 0});
  const double l = spec.module_w, j = spec.joint, r = arc.radius;
  const bool convex = f.bulge > 0;  // the face outside the curve: the joints close behind it
  const auto [sagitta, back] = chord_fit(r, l, j, depth, convex);
  if (back < kNarrowestJoint) {
    // Joints no wider than the least they may close to fit no curve: only wider ones do.
    const double least = depth * (l + j) / (j - kNarrowestJoint);
    const std::string remedy =
        j > kNarrowestJoint
            ? fmt::format("use a radius of at least {:.0f} mm, shorter units or wider joints",
                          std::ceil(least))
            : fmt::format(
                  "straight units need joints wider than {:g} mm to lie on a curve, or "
                  "units bent to it (arcs = \"bent\")",
                  kNarrowestJoint);
    refuse(
        path ? "path" : "plan",
        fmt::format("façade {} curves on a radius of {:.0f} mm, too tight for {:g} mm units "
                    "{:g} mm deep with {:g} mm joints: {} (a joint must keep {:g} mm); {}",
                    f.name, r, l, depth, j,
                    back < 0 ? fmt::format("the units would run {:.1f} mm into each other at "
                                           "the back",
                                           -back)
                             : fmt::format("the joints would close to {:.1f} mm at the back", back),
                    kNarrowestJoint, remedy));
  }
  return fmt::format(
      "façade {} is curved, radius {:.0f} mm at its face ({}): its {:g} mm units "
      "lie on chords {:.2f} mm inside the arc at their middle; each {:g} mm joint "
      "at the face is {:.1f} mm at the back, {:g} mm in",
      f.name, r, convex ? "convex" : "concave", l, sagitta, j, back, depth);
}

// A curved façade whose units are bent to its arc: each unit's developed width (its width on
// the strip, as ordered) and the chord and rise it is bent over.
std::string bent_units(const SurfaceFrame& f, const LayoutSpec& spec) {
  const double r = frame_radius(f), l = spec.module_w;
  const double chord = bent_chord(r, l);
  return fmt::format(
      "façade {} is curved, radius {:.0f} mm at its face ({}): its units are bent to the arc, "
      "each {:g} mm wide developed (as ordered) over a chord of {:.1f} mm, rising {:.1f} mm",
      f.name, r, f.bulge > 0 ? "convex" : "concave", l, chord, r - r * std::cos(l / (2 * r)));
}

}  // namespace

const SurfaceFrame* facade_named(const std::vector<SurfaceFrame>& facades,
                                 const std::string& name) {
  for (const SurfaceFrame& f : facades)
    if (f.name == name || std::to_string(f.index) == name) return &f;
  return nullptr;
}

Envelope envelope_of(const BuildingKeys& keys, const LayoutSpec& spec) {
  Envelope env;
  const double pitch_w = spec.module_w + spec.joint, pitch_h = spec.module_h + spec.joint;
  env.closed = !keys.plan.empty();
  env.facades = env.closed ? unroll_plan(keys.plan, keys.start, spec.module_w)
                           : unroll_path(keys.path, spec.module_w);
  for (SurfaceFrame& f : env.facades) f.base = keys.base;
  env.length = strip_length(env.facades);
  env.courses = whole_courses(keys.height, pitch_h);
  env.height = keys.height;
  if (!keys.heights.empty()) {
    if (keys.heights.size() != env.facades.size())
      refuse("heights", fmt::format("gives {} heights for {} edges: one per edge, in the plan's "
                                    "order",
                                    keys.heights.size(), env.facades.size()));
    for (SurfaceFrame& f : env.facades) {
      const double h = keys.heights[f.index];
      if (h > keys.height + kEps)
        refuse("heights", fmt::format("edge {} is {:g} mm high, above the wall's height of {:g} "
                                      "mm: height is the tallest",
                                      f.index, h, keys.height));
      whole_courses(h, pitch_h, "heights");
      if (h < keys.height - kEps) f.height = h;
    }
  }
  env.depth = keys.depth > 0 ? keys.depth : (spec.module_w - spec.joint) / 2;
  env.solid = keys.wall == "one-brick";
  if (env.solid) env.backing = keys.backing;
  if (env.depth >= spec.module_w)
    refuse("depth", fmt::format("{:g} mm is not less than the unit's length ({:g} mm): a unit "
                                "turns a corner on its end",
                                env.depth, spec.module_w));
  const double units = std::ceil(env.length / pitch_w) * static_cast<double>(env.courses);
  if (units > kMostEnvelopeUnits)
    throw ResourceLimitError(
        fmt::format("the envelope would hold about {:.0f} units, above the limit of {:.0f}: use "
                    "larger units, a lower wall or a smaller plan",
                    units, kMostEnvelopeUnits));
  for (SurfaceFrame& f : env.facades) {
    if (f.bulge == 0) continue;
    f.bent = keys.bent_on_arcs;
    env.notes.push_back(
        f.bent ? bent_units(f, spec)
               : joint_taper(f, spec, env.solid ? spec.module_w : env.depth, keys.plan.empty()));
  }
  const std::vector<NamedOpening> given = named_openings(keys, env.facades);
  // "W-12 on façade W at x 3375, sill 900": as the IFC, the sheets and the schedules name it.
  auto named = [&](size_t i, const SurfaceFrame* f, const Rect& r) {
    return fmt::format("{}{} at x {:g}, sill {:g}", given[i].name,
                       f ? " on façade " + f->name : std::string(), r.x, r.y);
  };
  size_t moved = 0;
  for (size_t i = 0; i < given.size(); ++i) {
    const BuildingOpening& o = given[i].opening;
    const SurfaceFrame* f = facade_named(env.facades, o.facade);
    if (!f)
      refuse("openings", fmt::format("{} names the façade \"{}\", which the plan does not "
                                     "have: name one by its compass point ({}) or its index",
                                     named(i, nullptr, o.rect), o.facade, [&] {
                                       std::string names;
                                       for (const SurfaceFrame& g : env.facades)
                                         names += (names.empty() ? "" : ", ") + g.name;
                                       return names;
                                     }()));
    Rect r = o.rect;
    if (keys.coursed_openings) {
      const double y = on_course(r.y, pitch_h), top = on_course(r.top(), pitch_h);
      moved += y != r.y || top != r.top();
      r.y = y, r.h = top - y;
      if (r.h <= 0)
        refuse("openings", fmt::format("{} is lower than one course", named(i, f, o.rect)));
    }
    if (r.right() > f->length + kEps)
      refuse("openings", fmt::format("{} runs to {:g} mm, past its corner at {:g} mm: an opening "
                                     "lies on one façade",
                                     named(i, f, r), r.right(), f->length));
    const double top = f->height > 0 ? f->height : env.height;
    if (r.top() > top + kEps)
      refuse("openings", fmt::format("{} reaches {:g} mm, above the wall's top at {:g} mm",
                                     named(i, f, r), r.top(), top));
    const Rect on_strip{f->start + r.x, r.y, r.w, r.h};
    for (size_t k = 0; k < env.openings.size(); ++k)
      if (overlaps(env.openings[k], on_strip)) {
        const SurfaceFrame& g = env.facades[env.opening_facade[k]];
        refuse("openings", fmt::format("{} overlaps {}: openings must stand apart", named(i, f, r),
                                       named(k, &g,
                                             Rect{env.openings[k].x - g.start, env.openings[k].y,
                                                  env.openings[k].w, env.openings[k].h})));
      }
    env.openings.push_back(on_strip);
    env.opening_facade.push_back(static_cast<size_t>(f - env.facades.data()));
    env.opening_type.push_back(o.type);
    env.opening_names.push_back(given[i].name);
  }
  if (moved)
    env.notes.push_back(
        fmt::format("{} opening(s) had their sill or head moved onto the nearest "
                    "course line ({:g} mm courses)",
                    moved, pitch_h));
  return env;
}

}  // namespace curdle
