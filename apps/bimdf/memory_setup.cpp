#include "memory_setup.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "bimdf/io.hpp"

namespace bimdf::cli {
namespace {

// Below this, an input's whole run takes a few milliseconds, and the re-exec (~1.2 ms) and the
// first huge page (~0.2 ms) cost more than huge pages save. Measured on the shared instances
// (whole `bimdf solve` processes): mushroom__flow_noalign_lemon_0 (2 KB) 2.8 ms without huge
// pages, 3.0 ms with, 3.9 ms with the re-exec; helmet__flow_1 (105 KB) even; cow__flow_0
// (375 KB) 5–15% faster with them.
constexpr std::uintmax_t kSmallInput = 256 << 10;

// How much of a file solve_heap_estimate reads to tell its format and, in .bimdf text, data
// from comments: 64 KiB is ~1,000 edges of a QuadWild file, and reading it from the page cache
// costs microseconds.
constexpr std::size_t kEstimateSample = 64 << 10;

// Whether the command line names at least one file and all of them are small.
bool only_small_files(char** argv) {
  bool any = false;
  for (char** arg = argv + 1; *arg; ++arg) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(*arg, error)) continue;
    const std::uintmax_t size = std::filesystem::file_size(*arg, error);
    if (error || size >= kSmallInput) return false;
    any = true;
  }
  return any;
}

// Whether the command line asks only for the usage or the version (or for nothing): then the
// program prints a few lines, and the re-exec would be most of its time (~3 ms).
bool asks_for_text_only(char** argv) {
  if (!argv[1]) return true;
  for (char** arg = argv + 1; *arg; ++arg) {
    const std::string a = *arg;
    if (a == "-h" || a == "--help" || a == "--version") return true;
  }
  return false;
}

}  // namespace

void configure_process_memory(char** argv) {
  // Why huge pages: every solve stage builds and drops networks of tens to hundreds of MB, and
  // on virtual machines each first touch of a 4 KiB page is an expensive fault (measured: a
  // sixth of the exact solve's time over the shared instances). With 2 MiB pages glibc's heap
  // faults ~500x less often. Only effective where transparent huge pages are enabled for
  // madvise (the Debian default) and glibc ≥ 2.35; elsewhere the tunable is ignored.
  constexpr const char* kTunable = "glibc.malloc.hugetlb";
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string current = tunables ? tunables : "";
  if (current.find(kTunable) == std::string::npos && !only_small_files(argv) &&
      !asks_for_text_only(argv)) {
    const std::string wanted = (current.empty() ? "" : current + ":") + kTunable + "=1";
    if (setenv("GLIBC_TUNABLES", wanted.c_str(), 1) == 0) {
      execv("/proc/self/exe", argv);  // returns only on failure
      if (tunables)
        setenv("GLIBC_TUNABLES", tunables, 1);
      else
        unsetenv("GLIBC_TUNABLES");
    }
  }
  // The solver allocates and frees the same large arrays round after round (min-cost flow and
  // matching networks of up to a few hundred MB). By default glibc serves each from a fresh
  // mmap and returns it on free, so every round pays the page faults again (a fifth of the
  // approximation's time on the largest shared instance). Keeping freed memory in the heap
  // avoids that at no cost in peak memory.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's maximum
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

HeapPrefault::HeapPrefault(std::uintmax_t bytes) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::uintmax_t kBlock = 8 << 20;  // below the mmap threshold: served by the heap
  // At most a quarter of the machine's memory: the estimate is a multiple of a file's size.
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0)
    bytes = std::min(bytes, static_cast<std::uintmax_t>(pages) * page_size / 4);
  if (bytes < (1 << 20) || std::thread::hardware_concurrency() < 2) return;
  std::vector<std::pair<char*, std::uintmax_t>> blocks;
  for (std::uintmax_t done = 0; done < bytes; done += kBlock) {
    const std::uintmax_t size = std::min(kBlock, bytes - done);
    char* block = static_cast<char*>(std::malloc(size));
    if (!block) break;
    blocks.emplace_back(block, size);
  }
  for (const auto& block : blocks) std::free(block.first);
  if (blocks.empty()) return;
  const std::uintptr_t page = page_size > 0 ? static_cast<std::uintptr_t>(page_size) : 4096;
  thread_ = std::thread([this, blocks, page] {
    for (auto it = blocks.rbegin(); it != blocks.rend() && !stop_.load(); ++it) {
      const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(it->first);
      const std::uintptr_t begin = (start + page - 1) & ~(page - 1);
      const std::uintptr_t end = (start + it->second) & ~(page - 1);
      if (end <= begin) continue;
      // Freed blocks may have merged and been handed out again: the advice leaves contents
      // alone, and a range no longer mapped only makes it fail.
      if (madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE) != 0) return;
    }
  });
#else
  (void)bytes;
#endif
}

HeapPrefault::~HeapPrefault() {
  stop_.store(true);
  wait();
}

void HeapPrefault::wait() {
  if (thread_.joinable()) thread_.join();
}

std::uintmax_t solve_heap_estimate(const std::string& path, bool exact) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return 0;
  // The reader's own format test, on the sample (a file with more leading blanks than that
  // counts as .bimdf text here: a larger estimate, nothing worse).
  std::ifstream in(path, std::ios::binary);
  std::string head(kEstimateSample, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.empty()) return 0;
  const bool json = detect_problem_format(head) == ProblemFormat::Json;
  const std::uintmax_t ratio = json ? (exact ? 10 : 8) : (exact ? 26 : 20);
  if (json) return size * ratio;
  // The ratios were measured on files whose only comment is the first line. '#' comments may
  // stand anywhere in .bimdf text, and a file that is mostly comments holds fewer edges than
  // its size says: scale by the share of the sample outside comments.
  std::uintmax_t data = 0;
  bool in_comment = false;
  for (const char c : head) {
    if (c == '#') in_comment = true;
    if (!in_comment) ++data;
    if (c == '\n') in_comment = false;
  }
  return static_cast<std::uintmax_t>(static_cast<long double>(size) * ratio * data / head.size());
}

}  // namespace bimdf::cli
