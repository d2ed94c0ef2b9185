#pragma once
// Seeded random numbers, identical bit for bit on every run of the same binary: xoshiro256++ seeded by
// SplitMix64 from (seed, stream), and our own normal generator (std::normal_distribution is
// implementation-defined). Independent streams per component: switching one sensor off never changes
// another's noise.
#include <array>
#include <cmath>
#include <cstdint>

namespace reckoner {

class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t sm = seed ^ (stream * 0xD1B54A32D192ED03ull);
    for (auto& w : s_) w = splitMix64(sm);
  }

  std::uint64_t nextU64() {
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

  /// Uniform on the open interval (0, 1).
  double uniform() { return (static_cast<double>(nextU64() >> 11) + 0.5) * 0x1.0p-53; }

  /// Standard normal, Marsaglia's polar method.
  double normal() {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    double u = 0.0, v = 0.0, s = 0.0;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * f;
    hasSpare_ = true;
    return u * f;
  }

  double normal(double mean, double sd) { return mean + sd * normal(); }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static std::uint64_t splitMix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::array<std::uint64_t, 4> s_{};
  bool hasSpare_ = false;
  double spare_ = 0.0;
};

/// Stream identifiers: one per random component of a simulation.
enum RngStream : std::uint64_t {
  kStreamTruth = 1,
  kStreamGps = 2,
  kStreamLoran = 3,
  kStreamSpeedlog = 4,
  kStreamGyro = 5,
  kStreamFilterInit = 6,
  kStreamRadar = 7,
  kStreamClutter = 8,        ///< radar clutter and per-sweep gyro scatter
  kStreamRadarImage = 9,     ///< the simulated radar image for chart matching (seed 004)
  kStreamRadarDisplay = 10,  ///< radar pictures made only for display (never disturbs a run's stream)
  kStreamGyroBias = 11,      ///< the gyro's calibration error (its own stream: the paper's stay as they were)
  kStreamLogScale = 12,      ///< the speedlog's scale-factor error
  kStreamTargetBase = 1000,  ///< target i uses kStreamTargetBase + i
  kStreamAisBase = 1'000'000,  ///< target i's AIS transponder uses kStreamAisBase + i
};

}  // namespace reckoner
