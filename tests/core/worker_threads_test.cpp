#include "core/worker_threads.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace chaser {
namespace {

// One worker per hardware thread, and one where the library cannot tell (it reports 0).
TEST(WorkerThreads, OnePerHardwareThreadAndAtLeastOne) {
  const unsigned reported = std::thread::hardware_concurrency();
  EXPECT_GE(default_worker_threads(), 1);
  if (reported > 0) {
    EXPECT_EQ(default_worker_threads(), static_cast<int>(reported));
  }
}

}  // namespace
}  // namespace chaser
