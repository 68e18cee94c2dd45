// The step profile's clock (World::Profile): on x86-64 where the processor's time-stamp counter
// runs at a constant rate (CPUID's invariant-TSC bit), that counter, read in a few cycles
// instead of the kernel's clock (six reads a step cost ≈ 1 % of the paper step); its ticks
// become seconds at the ratio steady_clock shows over the same span, taken when the profile is
// read. Elsewhere steady_clock's own ticks. Internal to physics/.
#pragma once

#include <chrono>
#include <cstdint>

namespace gearsim::physics {

class ProfileClock {
 public:
  ProfileClock();
  std::uint64_t now() const;
  // Seconds per tick: over the span since construction, against steady_clock.
  double seconds_per_tick() const;

 private:
  bool tsc_ = false;
  std::uint64_t tick0_ = 0;
  std::chrono::steady_clock::time_point t0_;
};

}  // namespace gearsim::physics
