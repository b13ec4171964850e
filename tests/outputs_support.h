// A small tile recipe run through the application, which the application tests share.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "app/outputs.h"
#include "app/reproduce.h"
#include "app/zone_in_cells.h"
#include "curdle/error.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace curdle::app {

inline constexpr const char* kTiles = R"(name = "tiles"
[lattice]
base = 2
dimension = 2
[[curds]]
name = "dark"
probabilities = ["3/4", "2/3"]
[field]
cells = [8, 8]
[layout]
kind = "tile"
tile = [300, 300]
joint = 5
)";

inline app::Run run_of(const std::string& text, std::vector<std::string> overrides = {}) {
  return test::run_recipe("tiles.toml", text, std::move(overrides));
}

inline std::vector<std::string> names(const std::vector<const Output*>& outputs) {
  std::vector<std::string> n;
  for (const Output* o : outputs) n.push_back(o->name);
  return n;
}

struct Notes : RunObserver {
  std::vector<std::string> notes;
  std::unique_ptr<ProgressTask> begin(const std::string&) override { return nullptr; }
  void skipped(const std::string& output, uint64_t count, const std::string& unit,
               uint64_t) override {
    notes.push_back(output + " skipped: " + std::to_string(count) + " " + unit);
  }
  void not_installed(const std::string& output, const std::string& why) override {
    notes.push_back(output + " not installed: " + why);
  }
};

}  // namespace curdle::app
