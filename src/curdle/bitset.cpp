#include "curdle/bitset.h"

#include <sys/mman.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cstdlib>
#include <cstring>
#include <new>

namespace curdle {
namespace {

constexpr size_t kHugePage = size_t{2} << 20;
// From a quarter of a huge page up: one fault zeroing 2 MiB costs less than the 64 or more
// small-page faults it replaces (each several microseconds on virtual machines).
constexpr size_t kMapAtLeast = size_t{256} << 10;

}  // namespace

Words::Words(const Words& other) {
  assign_zero(other.size_);
  if (size_) std::memcpy(data_, other.data_, size_ * sizeof(uint64_t));
}

Words::Words(Words&& other) noexcept
    : data_(other.data_),
      size_(other.size_),
      capacity_(other.capacity_),
      mapped_bytes_(other.mapped_bytes_) {
  other.data_ = nullptr;
  other.size_ = other.capacity_ = other.mapped_bytes_ = 0;
}

Words& Words::operator=(Words other) noexcept {
  std::swap(data_, other.data_);
  std::swap(size_, other.size_);
  std::swap(capacity_, other.capacity_);
  std::swap(mapped_bytes_, other.mapped_bytes_);
  return *this;
}

Words::~Words() { release(); }

void Words::release() {
  if (mapped_bytes_)
    ::munmap(data_, mapped_bytes_);
  else
    std::free(data_);
  data_ = nullptr;
  size_ = capacity_ = mapped_bytes_ = 0;
}

void Words::assign_zero(size_t count) {
  if (count <= capacity_) {
    if (count) std::memset(data_, 0, count * sizeof(uint64_t));
    size_ = count;
    return;
  }
  release();
  const size_t bytes = count * sizeof(uint64_t);
  if (bytes >= kMapAtLeast) {
    // Map a huge-page-aligned region (fresh mappings are zero) and trim the unaligned ends.
    const size_t length = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* raw = ::mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const uintptr_t start = reinterpret_cast<uintptr_t>(raw);
    const uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
    if (aligned > start) ::munmap(raw, aligned - start);
    const uintptr_t tail = aligned + length, end = start + length + kHugePage;
    if (end > tail) ::munmap(reinterpret_cast<void*>(tail), end - tail);
    ::madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);
    data_ = reinterpret_cast<uint64_t*>(aligned);
    mapped_bytes_ = length;
    capacity_ = length / sizeof(uint64_t);
  } else {
    data_ = static_cast<uint64_t*>(std::calloc(count ? count : 1, sizeof(uint64_t)));
    if (!data_) throw std::bad_alloc();
    capacity_ = count;
  }
  size_ = count;
}

uint64_t Bitset::count() const {
  const uint64_t* w = words.data();
  auto count_range = [w](size_t begin, size_t end) {
    uint64_t n = 0;
    for (size_t i = begin; i < end; ++i) n += std::popcount(w[i]);
    return n;
  };
  if (words.size() < (1u << 16)) return count_range(0, words.size());
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, words.size(), 1 << 14), uint64_t{0},
      [&](const tbb::blocked_range<size_t>& r, uint64_t n) {
        return n + count_range(r.begin(), r.end());
      },
      std::plus<>());
}

}  // namespace curdle
