#pragma once
// An exclusive lock on a campaign directory (flock on DIR/.lock), so that two processes never
// append to the same runs.csv (a resumed campaign while the killed one still runs, two Slurm jobs
// given the same --out). The kernel drops the lock when the process dies, SIGKILL included.
#include <string>

namespace chaser::campaign {

class DirLock {
 public:
  explicit DirLock(const std::string& dir);  // tries once, does not wait
  ~DirLock();
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;
  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace chaser::campaign
