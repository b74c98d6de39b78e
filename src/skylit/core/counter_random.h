// Counter-based random numbers: the u-th number of a stream is a hash of (stream key,
// u), so a sample's numbers depend only on which pixel, which sample and which
// dimension they are for, never on which thread drew them or in what order. Rendering
// with them gives the same bytes for any number of threads.
//
// The hash is SplitMix64's finaliser (Steele, Lea & Flood, "Fast splittable
// pseudorandom number generators", OOPSLA 2014), which passes BigCrush as a counter-mode
// generator; the stream key mixes its parts through the same finaliser.
#pragma once

#include <cstdint>

namespace skylit {

constexpr uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

class CounterRandom {
 public:
  // A stream for one (pixel, sample) of one seed.
  constexpr CounterRandom(uint64_t seed, uint64_t pixel, uint64_t sample)
      : key_(splitmix64(splitmix64(splitmix64(seed) ^ pixel) ^ sample)) {}

  // The next number, uniform in [0, 1) with 53 random bits.
  constexpr double uniform() {
    return static_cast<double>(splitmix64(key_ + 0x632be59bd9b4e019ULL * ++counter_) >> 11) * 0x1.0p-53;
  }

 private:
  uint64_t key_;
  uint64_t counter_ = 0;
};

}  // namespace skylit
