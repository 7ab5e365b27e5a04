#pragma once
// Deterministic random streams (docs/architecture.md: "Deterministic randomness").
//
// A run's seed comes from (campaign seed, run index); inside the run every noise source draws from
// its own stream, seeded by hashing the stream's name with the run seed, so adding a block never
// changes another block's draws. The generator is xoshiro256++ seeded through splitmix64, and the
// distributions are written here (not <random>'s) so that draws are identical on every standard
// library.
#include <cstdint>
#include <string_view>

namespace chaser {

// splitmix64 step: used for seeding and for mixing seeds.
std::uint64_t splitmix64(std::uint64_t& state);

// 64-bit FNV-1a of a stream name.
std::uint64_t hash_name(std::string_view name);

// Seed of run `run_index` in a campaign seeded with `campaign_seed`.
std::uint64_t run_seed(std::uint64_t campaign_seed, std::uint64_t run_index);

class RandomStream {
 public:
  RandomStream(std::uint64_t run_seed, std::string_view stream_name);

  std::uint64_t next_u64();
  double uniform();                          // [0, 1), 53-bit resolution
  double uniform(double lo, double hi);      // [lo, hi)
  double normal();                           // standard normal (Box-Muller, both values used)
  double normal(double mean, double sigma);
  // Normal with standard deviation sigma, redrawn until within +-k_sigma * sigma.
  double truncated_normal(double sigma, double k_sigma);

 private:
  std::uint64_t s_[4];
  double spare_normal_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace chaser
