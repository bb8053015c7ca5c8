// Running a deeply recursive computation on a thread whose stack is large enough for it.
//
// LEMON's MaxWeightedPerfectMatching unpacks nested blossoms recursively (extractBlossom), one
// stack frame per nesting level (our BlossomMatching's augmentation recurses likewise), and nesting
// grows with the graph: a 10^6-edge instance nests tens of thousands of levels deep and overflowed
// the default 8 MiB stack (SIGSEGV). The stack of a new thread is reserved address space, committed
// only as it is touched, so reserving generously costs nothing on graphs that do not need it.
#pragma once

#include <cstddef>
#include <functional>

namespace bimdf::detail {

// Calls `work` on a new thread with a stack of at least `stack_bytes` and waits for it;
// an exception thrown by `work` is rethrown here. When `stack_bytes` does not exceed the
// default stack, or a thread cannot be created with that stack, `work` runs on the calling
// thread instead (the result is the same; only the recursion headroom differs).
void run_with_stack(std::size_t stack_bytes, const std::function<void()>& work);

// The stack a perfect matching on `num_nodes` vertices gets: blossom nesting is bounded by
// num_nodes / 2, at about 180 bytes a recursion level in a release build and a few times that
// with sanitizers; below ~16k vertices the default stack suffices (0).
inline std::size_t matching_stack_bytes(int num_nodes) {
  return num_nodes < 16384 ? 0 : (std::size_t{64} << 20) + std::size_t(num_nodes) * 512;
}

}  // namespace bimdf::detail
