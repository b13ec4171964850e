// Canonical survival compares each byte of a Philox draw with the top byte of the stage's
// threshold (random_stream.h): below survives, equal is a tie that the next 56 bits decide.
// These compare 16 bytes at once with SSE2 where the CPU has it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "curdle/random_stream.h"

namespace curdle {

// 16 survival bytes of one draw against the threshold's top byte: which are below, which tie.
void compare_bytes(const RandomStream::Block& r, uint32_t top, uint32_t& below, uint32_t& tie);

// compare_bytes for `lanes` draws held as four word arrays (philox_batch.h).
void compare_lanes(const uint32_t* w0, const uint32_t* w1, const uint32_t* w2, const uint32_t* w3,
                   size_t lanes, uint32_t top, uint16_t* below, uint16_t* tie);

}  // namespace curdle
