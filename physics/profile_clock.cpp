#include "physics/profile_clock.hpp"

#if defined(__x86_64__)
#include <cpuid.h>
#include <x86intrin.h>
#endif

namespace gearsim::physics {

#if defined(__x86_64__)
ProfileClock::ProfileClock() : t0_(std::chrono::steady_clock::now()) {
  unsigned a = 0, b = 0, c = 0, d = 0;
  tsc_ = __get_cpuid(0x80000007u, &a, &b, &c, &d) && ((d >> 8) & 1u);  // invariant TSC
  tick0_ = now();
}
std::uint64_t ProfileClock::now() const {
  if (tsc_) return __rdtsc();
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
}
#else
ProfileClock::ProfileClock() : t0_(std::chrono::steady_clock::now()) { tick0_ = now(); }
std::uint64_t ProfileClock::now() const { return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()); }
#endif

double ProfileClock::seconds_per_tick() const {
  using Period = std::chrono::steady_clock::period;
  if (!tsc_) return static_cast<double>(Period::num) / static_cast<double>(Period::den);
  const std::uint64_t ticks = now() - tick0_;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  return ticks > 0 ? seconds / static_cast<double>(ticks) : 0.0;
}

}  // namespace gearsim::physics
