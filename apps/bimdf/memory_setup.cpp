#include "memory_setup.hpp"

#include <malloc.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace bimdf::cli {

void configure_process_memory(char** argv) {
  // Why huge pages: every solve stage builds and drops networks of tens to hundreds of MB, and
  // on virtual machines each first touch of a 4 KiB page is an expensive fault (measured: a
  // sixth of the exact solve's time over the shared instances). With 2 MiB pages glibc's heap
  // faults ~500x less often. Only effective where transparent huge pages are enabled for
  // madvise (the Debian default) and glibc ≥ 2.35; elsewhere the tunable is ignored.
  constexpr const char* kTunable = "glibc.malloc.hugetlb";
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string current = tunables ? tunables : "";
  if (current.find(kTunable) == std::string::npos) {
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

}  // namespace bimdf::cli
