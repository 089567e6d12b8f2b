#include "geometry/heap_tuning.h"

#include <cstdlib>  // defines __GLIBC__ under glibc (features.h)

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace linerlife {

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
#endif
}

}  // namespace linerlife
