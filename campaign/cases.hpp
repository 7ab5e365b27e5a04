#pragma once
// The fault cases of a campaign and the run layout: cases in the order given, each with its run
// count; global run index = offset of the case + j (docs/campaigns.md).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace chaser::campaign {

// Fonod 2015, section V: fault-free runs and the four fault cases of eqs. 3-5.
enum class FaultCase { kNone, kStuckOpen, kStuckClosed, kLeak, kLoss };

inline constexpr std::string_view kCaseNames = "none, stuck_open, stuck_closed, leak, loss";

std::string_view to_string(FaultCase c);
std::optional<FaultCase> parse_case(std::string_view name);

struct CaseRuns {
  FaultCase fault_case = FaultCase::kNone;
  std::int64_t runs = 0;
};

// Cases in run-index order, with their counts.
class RunLayout {
 public:
  explicit RunLayout(std::vector<CaseRuns> cases);
  const std::vector<CaseRuns>& cases() const { return cases_; }
  std::int64_t total_runs() const { return total_; }
  FaultCase case_of(std::int64_t run) const;  // run in [0, total_runs)

 private:
  std::vector<CaseRuns> cases_;
  std::int64_t total_ = 0;
};

// A shard: shard i of m runs the contiguous block [begin, end) of the global run indices: blocks of
// floor(N / m) runs, the first N mod m shards one run longer. Contiguous blocks merge by
// concatenation, in shard order.
struct Shard {
  int index = 0;  // i, 0-based
  int count = 1;  // m
};

struct RunRange {
  std::int64_t begin = 0;
  std::int64_t end = 0;  // one past the last
  std::int64_t size() const { return end - begin; }
};

RunRange shard_range(const Shard& shard, std::int64_t total_runs);

// "I/M" with 0 <= I < M; an error message (naming the option) otherwise.
struct ShardParse {
  std::optional<Shard> shard;
  std::string error;
};
ShardParse parse_shard(std::string_view text);

// --cases "none,leak" (empty: all five) with --runs "N" (every case) or "case=N,case=N" (those cases;
// without --cases, exactly the cases listed, in that order); a case without a count gets
// default_runs. An error message names the option and what is allowed.
struct LayoutParse {
  std::vector<CaseRuns> cases;
  std::string error;
};
LayoutParse parse_layout(std::string_view cases_text, std::string_view runs_text, std::int64_t default_runs);

}  // namespace chaser::campaign
