// A tiny, fully specified random number generator for planners that must be reproducible.
//
// Why not <random>: std::mt19937_64 itself is specified, but std::uniform_int_distribution,
// std::uniform_real_distribution, std::shuffle, ... are implementation-defined, so the same seed
// gives different plans with libstdc++, libc++ and MSVC. Every random decision in swarm goes
// through this header instead, and the same seed gives bit-identical results on every machine.
//
// Algorithms: xoshiro256** 1.0 (Blackman & Vigna, "Scrambled linear pseudorandom number
// generators", 2018) seeded through splitmix64 (Steele, Lea & Flood, "Fast splittable
// pseudorandom number generators", 2014), as its authors recommend.
//
// Not thread-safe; give every thread (or every planning call) its own Rng.
//
//   swarm::planner::Rng rng(swarm::planner::mix_seed(config.seed, round, group));
//   double u = rng.uniform01();          // [0, 1)
//   std::uint64_t i = rng.below(10);     // 0..9, unbiased
//   int d = rng.uniform_int(-3, 3);      // -3..3 inclusive
#pragma once

#include <cassert>
#include <cstdint>
#include <initializer_list>
#include <limits>

namespace swarm::planner {

// One splitmix64 step: advances `state` and returns a well-mixed 64-bit value.
constexpr std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Combines several integers (a seed, a round, a group id, ...) into one seed. Order matters:
// mix_seed(1, 2) != mix_seed(2, 1). Each value is fed through splitmix64 so nearby inputs
// (round 7 vs round 8) give unrelated streams.
constexpr std::uint64_t mix_seed(std::initializer_list<std::uint64_t> values) {
  std::uint64_t h = 0x6a09e667f3bcc909ULL;  // any fixed non-zero start
  for (std::uint64_t v : values) {
    std::uint64_t s = h ^ v;
    h = splitmix64(s);
  }
  return h;
}
template <class... Ints>
constexpr std::uint64_t mix_seed(Ints... values) {
  return mix_seed({static_cast<std::uint64_t>(values)...});
}

// xoshiro256**: 256 bits of state, period 2^256 - 1, passes BigCrush. Satisfies
// UniformRandomBitGenerator, but prefer the helpers below to std:: distributions (see above).
class Rng {
 public:
  using result_type = std::uint64_t;

  explicit constexpr Rng(std::uint64_t seed = 1) {
    // splitmix64 never yields four zero words in a row, so the state is never all zero.
    std::uint64_t sm = seed;
    for (std::uint64_t& w : s_) w = splitmix64(sm);
  }

  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }

  constexpr result_type next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  constexpr result_type operator()() { return next(); }

  // Uniform double in [0, 1): the top 53 bits scaled by 2^-53 (exact, no rounding).
  constexpr double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  // Uniform double in [lo, hi). Requires lo <= hi.
  constexpr double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

  // Uniform integer in [0, n), without modulo bias (rejection of the short last block).
  // Requires n > 0.
  constexpr std::uint64_t below(std::uint64_t n) {
    assert(n > 0);
    const std::uint64_t threshold = (0 - n) % n;  // 2^64 mod n
    for (;;) {
      const std::uint64_t r = next();
      if (r >= threshold) return r % n;
    }
  }

  // Uniform integer in [lo, hi], both inclusive. Requires lo <= hi.
  constexpr int uniform_int(int lo, int hi) {
    assert(lo <= hi);
    const std::uint64_t span =
        static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - static_cast<std::int64_t>(lo)) +
        1;
    return static_cast<int>(static_cast<std::int64_t>(lo) + static_cast<std::int64_t>(below(span)));
  }

  // True with probability p (p <= 0: never, p >= 1: always).
  constexpr bool bernoulli(double p) { return uniform01() < p; }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4] = {};
};

}  // namespace swarm::planner
