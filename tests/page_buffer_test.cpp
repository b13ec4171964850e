// Tests of page_buffer.h: the buffer is zeroed, writable to its last byte, aligned to a huge
// page when it is at least one, and moves without copying or freeing twice.
#include "export/drawing/page_buffer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <utility>

namespace curdle {
namespace {

constexpr size_t kHugePage = size_t{2} << 20;

TEST(PageBuffer, IsZeroedAndWritableToItsLastByte) {
  for (const size_t bytes :
       {size_t{1}, size_t{4096}, kHugePage - 1, kHugePage, 3 * kHugePage + 5}) {
    PageBuffer buffer(bytes);
    ASSERT_NE(buffer.data(), nullptr);
    EXPECT_EQ(buffer.size(), bytes);
    const auto* bytes_in = buffer.as<unsigned char>();
    size_t nonzero = 0;
    for (size_t i = 0; i < bytes; i += 997) nonzero += bytes_in[i] != 0;
    EXPECT_EQ(nonzero, 0u) << bytes;
    std::memset(buffer.data(), 0xab, bytes);
    EXPECT_EQ(buffer.as<unsigned char>()[bytes - 1], 0xab);
  }
}

TEST(PageBuffer, ALargeOneStartsOnAHugePage) {
  const PageBuffer large(kHugePage + 1);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(large.data()) % kHugePage, 0u);
  const PageBuffer small(100);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(small.data()) % 4096, 0u);  // a page of its own
}

TEST(PageBuffer, MovesItsPagesAlong) {
  PageBuffer first(kHugePage * 2);
  first.as<uint32_t>()[7] = 42;
  void* where = first.data();
  PageBuffer second(std::move(first));
  EXPECT_EQ(first.data(), nullptr);
  EXPECT_EQ(first.size(), 0u);
  EXPECT_EQ(second.data(), where);
  EXPECT_EQ(second.as<uint32_t>()[7], 42u);
  PageBuffer third(10);
  third = std::move(second);
  EXPECT_EQ(third.data(), where);
  EXPECT_EQ(third.size(), kHugePage * 2);
  const PageBuffer empty(0);
  EXPECT_EQ(empty.data(), nullptr);
}

}  // namespace
}  // namespace curdle
