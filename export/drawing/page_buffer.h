// A zeroed buffer on pages of its own, for the largest pictures a drawing makes (a sheet's
// canvas runs to tens of MB). It asks for 2 MB pages where the kernel gives them on request
// (transparent huge pages in "madvise" mode, Debian's default): where every 4 KB page fault
// costs some 30 µs, faulting in a screen's sheet took longer than drawing it. Where huge pages
// are off it is plain anonymous memory, zeroed by the kernel rather than by a pass of our own.
#pragma once

#include <cstddef>

namespace curdle {

class PageBuffer {
 public:
  // `bytes` of zeroes; throws std::bad_alloc when they cannot be mapped.
  explicit PageBuffer(size_t bytes);
  ~PageBuffer();
  PageBuffer(PageBuffer&& other) noexcept;
  PageBuffer& operator=(PageBuffer&& other) noexcept;
  PageBuffer(const PageBuffer&) = delete;
  PageBuffer& operator=(const PageBuffer&) = delete;

  void* data() const { return data_; }
  size_t size() const { return size_; }
  template <class T>
  T* as() const {
    return static_cast<T*>(data_);
  }

 private:
  void* mapping_ = nullptr;  // what munmap takes back: data_ and the slack that aligns it
  size_t mapped_ = 0;
  void* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace curdle
