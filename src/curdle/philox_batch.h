// Philox4x32-10 for many counters under one key, bit-identical to Random123's
// r123::Philox4x32 (Salmon et al., SC 2011), eight at a time with AVX2 where the CPU has it.
// Counters come in and results go out in place, as four arrays of words (structure of arrays).
#pragma once

#include <cstddef>
#include <cstdint>

namespace curdle {

void philox_in_place(uint32_t* w0, uint32_t* w1, uint32_t* w2, uint32_t* w3, size_t n,
                     uint32_t key0, uint32_t key1);

}  // namespace curdle
