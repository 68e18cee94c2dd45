// Which planet-pass sidebands a fixed sensor on the ring can see (McFadden & Smith 1985): planet
// i of N equally spaced ones sits at φ_c + 2πi/N; its ring mesh's k-th harmonic has the phase
// k·z_r·(φ_c + 2πi/N), and the sensor weighs it by a window of its position, whose Fourier
// series Σ_n W_n e^{in(φ_c + 2πi/N − φ_s)} shifts it by n·f_c. Summed over the planets the terms
// e^{2πi·i(k z_r + n)/N} cancel unless k·z_r + n ≡ 0 (mod N): at k·f_m + n·f_c only the n with
// n ≡ −k·z_r (mod N) survive. In phase (z_r ≡ 0 mod N, the paper's 96/3): n ≡ 0, sidebands N·f_c
// apart around every harmonic; sequential (95/3): shifted by −k·z_r — the asymmetry McFadden &
// Smith explained. Which survivor is largest depends on the window's W_n, not on this rule.
#pragma once

namespace gearsim {

// Whether the component at k·f_m + n·f_c survives at a fixed ring sensor (N planets, z_r ring teeth).
inline bool planet_pass_line_survives(int planets, int ring_teeth, int k, long n) {
  const long r = (static_cast<long>(k) * ring_teeth + n) % planets;
  return r == 0;
}

}  // namespace gearsim
