#pragma once
// Transparent huge pages for large, freshly reserved columns (TreeGraph, LineTree): faulting in
// hundreds of megabytes then takes a few hundred faults instead of ~50 000 per 200 MB.
#include <cstddef>

namespace fspm {

// Asks Linux to back [data, data + bytes) with huge pages (madvise MADV_HUGEPAGE). Only a hint;
// a no-op for small ranges and on other systems.
void advise_huge_pages(const void* data, std::size_t bytes);

// advise_huge_pages for the allocated capacity of each column (a std::vector or alike).
template <typename... Columns>
void advise_huge_page_columns(const Columns&... columns) {
  (advise_huge_pages(columns.data(), columns.capacity() * sizeof(typename Columns::value_type)),
   ...);
}

}  // namespace fspm
