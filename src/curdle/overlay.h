// Overlaying n curds on one lattice: each finest cell takes the value
// v = sum_i 2^i [curd i survived], one of 2^n (Cirovic 2014, eq. 1).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "curdle/curd.h"

namespace curdle {

// Cells of each value over the generated box (2^n entries; value 0 = no curd survived).
std::vector<uint64_t> value_counts(const CurdField& field);

// A copy of `field` in which only cells meeting `view` survive, at every stage.
CurdField restrict_to(const CurdField& field, const Box& view);

// Each value's expected share of the finest cells: the product over the curds of their part
// of it (curds are drawn independently), a plain curd's P_K or 1 - P_K, a Markov curd's state
// share (markov.h). Density fields are not taken into account (report.h does that).
std::vector<double> expected_value_shares(const Design& design);

// "empty" for 0, otherwise the names of the curds present joined by '+'.
std::string value_label(uint32_t value, const std::vector<CurdSpec>& curds);

// Calls row(y, z, values) for each row of `view` along x, rows in y then z order, values of
// the cells from x = view.origin[0] on. Streams: memory is one row.
// `progress`, when given, hears the fraction of rows done now and then.
void scan_rows(const CurdField& field, const Box& view,
               const std::function<void(int64_t y, int64_t z, std::span<const uint16_t>)>& row,
               const std::function<void(double)>& progress = {});

// Values of the cells of `view`, row-major (x fastest, then y, then z).
std::vector<uint16_t> values_in(const CurdField& field, const Box& view);

}  // namespace curdle
