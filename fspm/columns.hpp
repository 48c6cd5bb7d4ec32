#pragma once
// One operation over several columns of a structure-of-arrays tree (TreeGraph, LineTree) at once,
// so that each class names its columns once per operation.
#include <cstddef>

namespace fspm {

template <typename... Columns>
void reserve_columns(std::size_t n, Columns&... columns) {
  (columns.reserve(n), ...);
}

template <typename... Columns>
void resize_columns(std::size_t n, Columns&... columns) {
  (columns.resize(n), ...);
}

template <typename... Columns>
void clear_columns(Columns&... columns) {
  (columns.clear(), ...);
}

}  // namespace fspm
