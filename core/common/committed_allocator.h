#pragma once
// An allocator that commits the memory it hands out: every byte is written once when it is allocated,
// so that the pages are the program's from then on. A table reserved for its configured capacity
// (the tracker's: 1000 tracks) then costs its whole size from the start, instead of page by page as
// the traffic reaches new highs: the resident memory of hour 24 is that of hour 1 (the soak,
// docs/robustness.md), and a machine short of memory shows it when the program starts, not in the
// busiest hour of a watch.
#include <cstddef>
#include <cstring>
#include <memory>

namespace reckoner {

template <class T>
struct CommittedAllocator {
  using value_type = T;

  CommittedAllocator() noexcept = default;
  template <class U>
  explicit CommittedAllocator(const CommittedAllocator<U>& /*other*/) noexcept {}

  [[nodiscard]] T* allocate(std::size_t n) {
    T* p = std::allocator<T>{}.allocate(n);
    std::memset(static_cast<void*>(p), 0, n * sizeof(T));  // raw storage, before any T lives in it
    return p;
  }
  void deallocate(T* p, std::size_t n) noexcept { std::allocator<T>{}.deallocate(p, n); }

  template <class U>
  friend bool operator==(const CommittedAllocator& /*a*/, const CommittedAllocator<U>& /*b*/) noexcept {
    return true;
  }
};

}  // namespace reckoner
