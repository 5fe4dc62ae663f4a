/**
 * @file    penumbraLargeArrays.h
 * @brief   Storage for the large arrays that geometry rebuilds fill: huge pages where the system
 *          offers them on request.
 *
 * A build of millions of triangles touches hundreds of megabytes for the first time, and each
 * first touch of a 4 KiB page is a page fault. On a virtual machine a fault can cost more than
 * the work done in the page: a 4M-triangle topology's first build spent most of its time there
 * (results.md, "Growing data and first builds"). Linux's transparent huge pages, where they are
 * enabled on request (`madvise`, as on the machine measured) or always, map 2 MiB at a time.
 */
#ifndef penumbraLargeArrays_h
#define penumbraLargeArrays_h

#include <cstddef>
#include <vector>

namespace penumbra
{
/// Asks the system to back the whole 2 MiB pages inside [data, data + bytes) with huge pages
/// when they are first touched. Call it before the storage is written. Does nothing where no
/// whole huge page lies inside, on systems without transparent huge pages, or where they are
/// off.
void AdviseHugePages(const void* data, std::size_t bytes);

/// Reserves storage for `count` elements of `values`, empty, with AdviseHugePages on it.
template <typename T>
void ReserveLarge(std::vector<T>& values, std::size_t count)
{
  values.clear();
  values.reserve(count);
  AdviseHugePages(values.data(), count * sizeof(T));
}
} // namespace penumbra

#endif
