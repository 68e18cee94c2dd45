#include "analysis/resonator.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace gearsim {

Resonator::Resonator(double f_r, double zeta, double mass, double fs) : fs_(fs) {
  if (!(fs > 0) || !std::isfinite(fs)) throw InputError("resonator: the sample rate must be a positive number of Hz");
  if (!(f_r > 0 && f_r < fs / 2))
    throw InputError("resonator: resonance " + std::to_string(f_r) + " Hz must lie in (0, " + std::to_string(fs / 2) + ") Hz");
  if (!(zeta > 0) || !std::isfinite(zeta)) throw InputError("resonator: expected a damping ratio > 0");
  if (!(mass > 0) || !std::isfinite(mass)) throw InputError("resonator: expected an effective mass > 0 in kg");
  const double w = 2 * std::numbers::pi * f_r;
  const double K = w / std::tan(w / (2 * fs));  // bilinear transform, prewarped at ω_r
  const double a0 = K * K + 2 * zeta * w * K + w * w;
  b0_ = K * K / mass / a0;
  b1_ = -2 * b0_;
  b2_ = b0_;
  a1_ = (2 * w * w - 2 * K * K) / a0;
  a2_ = (K * K - 2 * zeta * w * K + w * w) / a0;
}

double Resonator::step(double x) {
  const double y = b0_ * x + z1_;
  z1_ = b1_ * x - a1_ * y + z2_;
  z2_ = b2_ * x - a2_ * y;
  return y;
}

std::complex<double> Resonator::response(double f_hz) const {
  const std::complex<double> zi = std::polar(1.0, -2 * std::numbers::pi * f_hz / fs_);  // z⁻¹
  return (b0_ + b1_ * zi + b2_ * zi * zi) / (1.0 + a1_ * zi + a2_ * zi * zi);
}

}  // namespace gearsim
