#include "core/deep_stack.hpp"

#include <pthread.h>

#include <exception>

namespace bimdf::detail {
namespace {

constexpr std::size_t kDefaultStack = std::size_t{8} << 20;

struct Job {
  const std::function<void()>* work;
  std::exception_ptr error;
};

void* run_job(void* arg) {
  Job& job = *static_cast<Job*>(arg);
  try {
    (*job.work)();
  } catch (...) {
    job.error = std::current_exception();
  }
  return nullptr;
}

}  // namespace

void run_with_stack(std::size_t stack_bytes, const std::function<void()>& work) {
  if (stack_bytes <= kDefaultStack) {
    work();
    return;
  }
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) {
    work();
    return;
  }
  Job job{&work, nullptr};
  pthread_t thread;
  const bool started = pthread_attr_setstacksize(&attr, stack_bytes) == 0 &&
                       pthread_create(&thread, &attr, run_job, &job) == 0;
  pthread_attr_destroy(&attr);
  if (!started) {
    work();
    return;
  }
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
}

}  // namespace bimdf::detail
