#pragma once
// The allocator of structure-of-arrays columns that bulk writers fill right after growing them
// (LineTree, TreeGraph::Appender).
#include <memory>
#include <new>
#include <utility>

namespace fspm {

// std::allocator that leaves new elements uninitialised: a column grown by resize() for a bulk
// writer that fills every element is not zeroed first (that extra pass costs a third of the
// time at memory speed).
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace fspm
