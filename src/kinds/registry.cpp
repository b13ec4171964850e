#include "kinds/registry.h"

#include <mutex>
#include <stdexcept>

#include "curdle/check.h"
#include "kinds/blocks.h"
#include "kinds/facade.h"
#include "kinds/park.h"
#include "kinds/paving.h"
#include "kinds/perforation.h"
#include "kinds/rhythm.h"
#include "kinds/tile.h"

namespace curdle {
namespace {

struct Registry {
  std::mutex mutex;
  std::vector<std::unique_ptr<const LayoutKind>> owned;
  std::vector<const LayoutKind*> kinds;

  Registry() {
    add(std::make_unique<TileKind>());
    add(std::make_unique<PavingKind>());
    add(std::make_unique<FacadeKind>());
    add(std::make_unique<PerforationKind>());
    add(std::make_unique<ParkKind>());
    add(std::make_unique<RhythmKind>());
    add(std::make_unique<BlocksKind>());
  }
  void add(std::unique_ptr<const LayoutKind> kind) {
    for (const LayoutKind* k : kinds)
      CHECK(k->name() != kind->name(),
            "layout kind \"" + std::string(kind->name()) + "\" is registered twice");
    kinds.push_back(kind.get());
    owned.push_back(std::move(kind));
  }
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

const std::vector<const LayoutKind*>& layout_kinds() { return registry().kinds; }

const LayoutKind* find_layout_kind(std::string_view name) {
  if (name == "façade") name = "facade";
  for (const LayoutKind* k : layout_kinds())
    if (k->name() == name) return k;
  return nullptr;
}

const LayoutKind& layout_kind(std::string_view name) {
  const LayoutKind* k = find_layout_kind(name);
  CHECK(k, "no layout kind \"" + std::string(name) + "\" is registered");
  return *k;
}

void register_layout_kind(std::unique_ptr<const LayoutKind> kind) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  r.add(std::move(kind));
}

std::string layout_kind_names() {
  std::string names;
  for (const LayoutKind* k : layout_kinds())
    names += (names.empty() ? "\"" : ", \"") + std::string(k->name()) + "\"";
  return names;
}

}  // namespace curdle
