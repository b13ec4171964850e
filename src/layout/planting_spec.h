// What the landscape contractor orders for a kind of standing object (a park's tree, bench):
// the recipe's botanical or product name and the nursery's sizes, one per curd (or Markov
// state) that places objects: two curds' trees of one type may be two species.
#pragma once

#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace curdle {

struct PlantingSpec {
  std::string species;                // botanical or product name; empty: the type says it
  std::array<double, 2> girth{0, 0};  // stem girth at 1 m above ground, cm, from-to; 0: not given
  double root_ball = 0;               // root ball diameter, mm; 0: not given
  std::array<double, 2> pit{0, 0};    // the tree pit dug in plan, mm, width x length; 0: none
  std::string member;                 // the curd or state placing it: its elements' key.part
  bool pit_given() const { return pit[0] > 0 && pit[1] > 0; }
  // The girth as a nursery writes it: "16-18", "20"; "" when not given.
  std::string girth_text() const {
    if (girth[0] <= 0) return "";
    std::ostringstream text;  // as %g writes them
    text << girth[0];
    if (girth[1] != girth[0]) text << '-' << girth[1];
    return text.str();
  }
};

// A park's planting (the park kind's own record on its layout): what the contractor orders, one
// order per curd that places standing objects.
struct ParkPlanting {
  std::vector<PlantingSpec> orders;
  bool any_pit() const {
    for (const PlantingSpec& p : orders)
      if (p.pit_given()) return true;
    return false;
  }
};

}  // namespace curdle
