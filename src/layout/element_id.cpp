#include "layout/element_id.h"

#include <fmt/format.h>

namespace curdle {

std::string ElementId::text() const {
  std::string s = fmt::format("{}-", kind);
  if (level) s += fmt::format("L{:0{}}-", *level, digits);
  s += fmt::format("R{:0{}}-C{:0{}}", row, digits, column, digits);
  if (!part.empty()) {
    s += '-';
    s += part;
  }
  return s;
}

ElementId ElementId::within(char piece_kind, std::string piece) const {
  ElementId id = *this;
  id.kind = piece_kind;
  id.part = std::move(piece);
  return id;
}

ElementId ElementId::as(char piece_kind) const { return within(piece_kind, part); }

}  // namespace curdle
