// McFadden's separation of the individual planets' time-synchronous averages from one fixed
// sensor on the ring (P. D. McFadden, "A technique for calculating the time domain averages of
// the vibration of the individual planet gears and the sun gear in an epicyclic gearbox",
// J. Sound Vib. 144 (1991) 163–172): a sample is credited to planet i only while planet i passes
// the sensor, weighted by a window of the planet's angular distance from it, and is averaged by
// the planet's own rotation relative to the carrier (which tooth is in mesh). What the other
// planets' meshes add, far from the sensor, is windowed out.
#pragma once

#include <string>
#include <vector>

namespace gearsim {

// The Hann window of full width `width_rad` about 0, at the angle `delta_rad` (wrapped to
// (−π, π]): 1 at 0, 0 beyond ±width/2. The planet-pass window of the sensor model and of the
// separation.
double planet_pass_hann(double delta_rad, double width_rad);

struct PlanetSeparatedAverage {
  int samples_per_revolution = 0;
  // Per grid angle j·2π/samples_per_revolution of the planet's turn; bins the windows never
  // reached are interpolated between their seen neighbours (coverage says how many were seen).
  std::vector<double> mean;
  std::vector<double> weight;  // Σ window weights that went into mean[j] (0: never seen)
  double coverage = 0;  // share of the grid with weight > 0
  double passes = 0;  // sensor passes of the planet in the record
};

// signal, planet_position_rad (the planet centre's angle about the set's centre, world, unwrapped)
// and planet_spin_rad (its turn relative to the carrier, unwrapped) sampled together. The window
// is a Hann of full width window_width_rad about sensor_angle_rad. InputError on different
// lengths, fewer than 2 samples, a width outside (0, 2π], samples_per_revolution < 4, or a record
// in which the planet never passes the sensor.
PlanetSeparatedAverage planet_separated_average(const std::vector<double>& signal, const std::vector<double>& planet_position_rad,
                                                const std::vector<double>& planet_spin_rad, double sensor_angle_rad,
                                                double window_width_rad, int samples_per_revolution);

// The sun's average from the same sensor (McFadden 1991): a sample weighted by planet i's window
// is credited to the sun's turn relative to the carrier less planet i's position on the carrier
// (which sun tooth meets planet i), summed over the planets. planet_position_rad[i] and
// planet_offset_rad[i] per planet (its position angle in the world, and its position on the
// carrier); sun_rel_carrier_rad the sun's turn relative to the carrier, all sampled with signal.
PlanetSeparatedAverage sun_separated_average(const std::vector<double>& signal, const std::vector<std::vector<double>>& planet_position_rad,
                                             const std::vector<double>& planet_offset_rad, const std::vector<double>& sun_rel_carrier_rad,
                                             double sensor_angle_rad, double window_width_rad, int samples_per_revolution);

}  // namespace gearsim
