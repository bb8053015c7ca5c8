// The `bimdf` program's heap pre-faulting (apps/bimdf/memory_setup.hpp): the memory it faults in
// is what the next allocations get, without a fault, and what they hold is left alone.
#include <gtest/gtest.h>
#include <malloc.h>
#include <sys/mman.h>
#include <sys/resource.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "memory_setup.hpp"

namespace {

using bimdf::cli::HeapPrefault;
using bimdf::cli::solve_heap_estimate;

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Whether this kernel knows MADV_POPULATE_WRITE (Linux ≥ 5.14); HeapPrefault does nothing
// where it does not.
bool kernel_populates() {
#ifdef MADV_POPULATE_WRITE
  void* page = mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (page == MAP_FAILED) return false;
  const bool ok = madvise(page, 4096, MADV_POPULATE_WRITE) == 0;
  munmap(page, 4096);
  return ok;
#else
  return false;
#endif
}

// Allocates `bytes` in 1 MiB blocks (glibc serves them from the heap) and writes every byte.
std::vector<char*> allocate_and_touch(std::size_t bytes, char fill) {
  std::vector<char*> blocks;
  for (std::size_t done = 0; done < bytes; done += 1 << 20) {
    blocks.push_back(static_cast<char*>(std::malloc(1 << 20)));
    std::memset(blocks.back(), fill, 1 << 20);
  }
  return blocks;
}

// gcc defines __SANITIZE_ADDRESS__ under -fsanitize=address; clang answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define BIMDF_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BIMDF_TEST_UNDER_ASAN 1
#endif
#endif

TEST(HeapPrefault, NextAllocationsFindTheirPagesFaultedIn) {
#if defined(BIMDF_TEST_UNDER_ASAN)
  GTEST_SKIP() << "AddressSanitizer's allocator keeps freed blocks in quarantine";
#endif
  if (!kernel_populates()) GTEST_SKIP() << "this kernel has no MADV_POPULATE_WRITE";
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "HeapPrefault needs two cores";
  // As configure_process_memory sets them: freed memory stays in the heap.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  constexpr std::size_t kBytes = 48 << 20, kPages = kBytes / 4096;
  HeapPrefault(kBytes + (4 << 20)).wait();
  const long before = minor_faults();
  const std::vector<char*> prefaulted = allocate_and_touch(kBytes, 1);
  const long with_prefault = minor_faults() - before;
  // The same amount again, beyond what was pre-faulted: every page a first touch.
  const std::vector<char*> fresh = allocate_and_touch(kBytes, 2);
  const long without = minor_faults() - before - with_prefault;
  EXPECT_GT(without, static_cast<long>(kPages / 2));  // 4 KiB pages: one fault each
  EXPECT_LT(with_prefault, static_cast<long>(kPages / 20)) << "without: " << without;
  for (char* block : prefaulted) std::free(block);
  for (char* block : fresh) std::free(block);
}

// The thread may still be faulting in blocks that this one already allocated and writes: their
// contents stay what this thread wrote.
TEST(HeapPrefault, LeavesWhatTheProgramWritesAlone) {
  constexpr std::size_t kBytes = 64 << 20;
  std::vector<char*> blocks;
  {
    HeapPrefault prefault(kBytes);
    for (std::size_t done = 0; done < kBytes; done += 1 << 20) {
      blocks.push_back(static_cast<char*>(std::malloc(1 << 20)));
      for (std::size_t i = 0; i < (1 << 20); i += 512)
        blocks.back()[i] = static_cast<char>(blocks.size() + i / 512);
    }
    prefault.wait();  // every block faulted in, some after this thread wrote to them
  }
  std::size_t wrong = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    for (std::size_t i = 0; i < (1 << 20); i += 512)
      wrong += blocks[b][i] != static_cast<char>(b + 1 + i / 512);
    std::free(blocks[b]);
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(HeapPrefault, EstimateScalesTheFileSizeByFormatAndMode) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "bimdf_prefault";
  std::filesystem::create_directories(dir);
  const std::string text = (dir / "p.bimdf").string(), json = (dir / "p.json").string();
  std::ofstream(text) << "# libSatsuma BiMDF file\n1\n0\n0\n";
  std::ofstream(json) << "  \n{\"format\": \"bimdf-problem\", \"version\": 1}\n";
  const std::uintmax_t text_size = std::filesystem::file_size(text);
  const std::uintmax_t json_size = std::filesystem::file_size(json);
  // The first line, 24 bytes with its newline, is a comment: 20 × (size − 24).
  ASSERT_EQ(text_size, 30u);
  EXPECT_EQ(solve_heap_estimate(text, false), 20 * 6u);
  EXPECT_EQ(solve_heap_estimate(text, true), 26 * 6u);
  EXPECT_EQ(solve_heap_estimate(json, false), 8 * json_size);
  EXPECT_EQ(solve_heap_estimate(json, true), 10 * json_size);
  EXPECT_EQ(solve_heap_estimate((dir / "missing.bimdf").string(), true), 0u);
  // A file of comments beyond the sample: only the sample's share of data counts, 1 byte in 4.
  const std::string commented = (dir / "c.bimdf").string();
  {
    std::ofstream out(commented);
    for (int i = 0; i < 30000; ++i) out << "0\n#cccc\n";
  }
  EXPECT_EQ(std::filesystem::file_size(commented), 240000u);
  EXPECT_EQ(solve_heap_estimate(commented, true), 26u * 240000u / 4);
  std::ofstream(text) << "";
  EXPECT_EQ(solve_heap_estimate(text, true), 0u);
  std::filesystem::remove_all(dir);
}

}  // namespace
