#include "core/random.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace chaser {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t hash_name(std::string_view name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

std::uint64_t run_seed(std::uint64_t campaign_seed, std::uint64_t run_index) {
  std::uint64_t state = campaign_seed ^ (0xa0761d6478bd642fULL * (run_index + 1));
  splitmix64(state);
  return splitmix64(state);
}

RandomStream::RandomStream(std::uint64_t seed, std::string_view stream_name) {
  std::uint64_t state = seed ^ hash_name(stream_name);
  for (auto& word : s_) word = splitmix64(state);
}

static inline std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

std::uint64_t RandomStream::next_u64() {
  const std::uint64_t result = rotl(s_[0] + s_[3], 23) + s_[0];
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double RandomStream::uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

double RandomStream::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

double RandomStream::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_normal_;
  }
  // 1 - u lies in (0, 1], so the logarithm is finite.
  const double radius = std::sqrt(-2.0 * std::log(1.0 - uniform()));
  const double angle = 2.0 * kPi * uniform();
  spare_normal_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

double RandomStream::normal(double mean, double sigma) { return mean + sigma * normal(); }

double RandomStream::truncated_normal(double sigma, double k_sigma) {
  if (sigma == 0.0) return 0.0;
  for (;;) {  // acceptance is 99.7 % at k = 3; k_sigma >= 1 is validated by callers
    const double x = normal();
    if (std::abs(x) <= k_sigma) return sigma * x;
  }
}

}  // namespace chaser
