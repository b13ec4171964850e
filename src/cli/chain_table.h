// A fitted Markov curd on the terminal: its entries with their intervals, its stages' states
// and boxes beside the chain's, and which reading the cells support. `fit` and `measure` print it.
#pragma once

#include "app/chain_reading.h"

namespace curdle::cli {

void print_chain(const app::ChainReading& chain);
void print_levels(const app::ChainReading& chain);
void print_readings(const app::ChainReading& chain);

}  // namespace curdle::cli
