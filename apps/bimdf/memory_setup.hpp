// Process-wide memory settings of the `bimdf` program (never of the library: they affect every
// allocation in the process, so only a program may choose them).
#pragma once

namespace bimdf::cli {

// Call first thing in main(), before anything is read or allocated in earnest. Asks glibc to
// back the heap with transparent huge pages — by re-executing the program once with
// glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES, since glibc reads its tunables only at start
// — unless GLIBC_TUNABLES already names that tunable (set it to 0 to opt out), every file
// named on the command line is small (under 256 KiB: the run takes milliseconds, and the
// re-exec would cost more than huge pages save), or the re-exec fails (then the program simply
// goes on). Then keeps freed memory in the heap (mallopt).
void configure_process_memory(char** argv);

}  // namespace bimdf::cli
