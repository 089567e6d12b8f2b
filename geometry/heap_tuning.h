// heap_tuning.h - keep the memory the program frees for its next allocations.
#pragma once

namespace linerlife {

/// The coupled wear run frees and allocates the same buffers (a ring of some
/// 5,000 surface elements, its loads and rates) at every remesh. glibc's
/// malloc gives the top of its heap back to the kernel once 128 KiB of it are
/// free and takes it again through page faults, which cost the bundled mill's
/// 51-revolution wear run 45-61 % of its wall (0.69-0.96 s against 0.38 s;
/// docs/benchmarks.md, ## Wear).
/// This raises the trim threshold to 512 MiB and fixes the mmap threshold at
/// glibc's 64-bit maximum (32 MiB, so that a finer ring's buffers above 128
/// KiB come from the heap too), and freed pages stay in the process (its peak
/// memory is unchanged). Call once at the start of main(); a no-op outside
/// glibc.
void keep_freed_memory();

}  // namespace linerlife
