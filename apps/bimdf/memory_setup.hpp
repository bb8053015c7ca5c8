// Process-wide memory settings of the `bimdf` program (never of the library: they affect every
// allocation in the process, so only a program may choose them).
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

namespace bimdf::cli {

// Call first thing in main(), before anything is read or allocated in earnest. Asks glibc to
// back the heap with transparent huge pages — by re-executing the program once with
// glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES, since glibc reads its tunables only at start
// — unless GLIBC_TUNABLES already names that tunable (set it to 0 to opt out), every file
// named on the command line is small (under 256 KiB: the run takes milliseconds, and the
// re-exec would cost more than huge pages save), the command line asks only for --help or
// --version (or is empty), or the re-exec fails (then the program simply goes on). Then keeps
// freed memory in the heap (mallopt).
void configure_process_memory(char** argv);

// Heap memory faulted in on another core while this one reads the input. The first touch of a
// page costs a fault in which the kernel (and, on a virtual machine, the host) clears it: in
// `perf` profiles of bull__flow_1's approximation that clearing took from 2% to 44% of the run,
// varying with the host from run to run. Construction allocates `bytes` in blocks and frees
// them at once — they stay in the heap (configure_process_memory's mallopt), and the next
// allocations are served from them — then a thread asks the kernel to fault them in writable
// (MADV_POPULATE_WRITE, Linux ≥ 5.14: no byte is written, so the main thread may already be
// using them), from the top down, since the main thread allocates from the bottom. From 1 MiB
// on (files from ~40 KB, ~1,000 edges) it pays: on the 23 shared instances of 41–160 KB it took
// 13% off the exact solves and 15% off the approximations (they had none at a 4 MiB threshold).
// Below that, on a single core, or where the kernel lacks the advice it does nothing (a 6 KB
// file's whole run, 2.7 ms, took 0.3 ms longer with the thread). Faults in at most a quarter of
// the machine's memory. The destructor stops the thread after the block it is faulting in
// (8 MiB; a run that ends early, on an input error, does not wait for the rest) and waits for it.
class HeapPrefault {
 public:
  explicit HeapPrefault(std::uintmax_t bytes);
  ~HeapPrefault();
  // Waits until every block is faulted in (or the advice failed).
  void wait();
  HeapPrefault(const HeapPrefault&) = delete;
  HeapPrefault& operator=(const HeapPrefault&) = delete;

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// What `bimdf solve` of the problem file `path` will at least allocate (0 if it cannot tell): the
// file's size times the smallest ratio of peak memory to file size measured on the larger
// shared instances — .bimdf text: 20 for the approximation, 26 for the exact solve (bull's exact
// peak is 35 times its file, but above 26 the pre-faulted blocks raised it); JSON, 2.5 times
// larger per edge: 8 and 10 — so that pre-faulting it does not raise the peak. Those files have
// one comment line; for .bimdf text the size is first scaled by the share of its first 64 KiB
// that lies outside '#' comments, so that a file of mostly comments is not taken for a large
// problem.
std::uintmax_t solve_heap_estimate(const std::string& path, bool exact);

}  // namespace bimdf::cli
