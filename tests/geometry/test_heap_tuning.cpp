// keep_freed_memory() (geometry/heap_tuning.h): a large block freed by the
// program stays in its heap for the next allocation instead of going back to
// the kernel (the wear run's remeshes page-faulted their buffers back in).
// Its own test program (tests/geometry/CMakeLists.txt): the checks need a
// fresh heap, whose thresholds no earlier test has moved.
#include <cstdlib>

#include <catch2/catch.hpp>

#include "geometry/heap_tuning.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

using namespace linerlife;

TEST_CASE("keep_freed_memory: a freed 4 MiB block stays in the heap", "[geometry][heap]") {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)  // ASan has its own allocator
  keep_freed_memory();
  const size_t n = 4u << 20;
  const struct mallinfo2 before = mallinfo2();
  char* p = static_cast<char*>(std::malloc(n));
  REQUIRE(p != nullptr);
  for (size_t i = 0; i < n; i += 4096) p[i] = 1;  // touch every page
  const struct mallinfo2 held = mallinfo2();
  // from the heap (glibc's default would map a block this large on its own)
  CHECK(held.hblkhd == before.hblkhd);
  CHECK(held.arena >= before.arena + n);
  std::free(p);
  const struct mallinfo2 after = mallinfo2();
  // not trimmed: the heap keeps the freed pages (the default trims above 128 KiB)
  CHECK(after.arena == held.arena);
  CHECK(after.fordblks >= before.fordblks + n);
#else
  SUCCEED("not glibc's malloc (or under ASan): keep_freed_memory() does not apply");
#endif
}
