#include "fe/potential_energy.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "geometry/involute.hpp"
#include "geometry/constants.hpp"

namespace gearsim::fe {
namespace {

using gearsim::constants::kPi;

// Reject what the model does not cover, naming the field.
void validate(const PotentialEnergyPairDef& d) {
  const std::string w = "potential-energy stiffness: ";
  if (d.z1 < 5) throw InputError(w + "z1 must be an external gear with >= 5 teeth, got " + std::to_string(d.z1));
  if (d.z2 == 0 || std::abs(d.z2) < 5) throw InputError(w + "|z2| must be >= 5, got " + std::to_string(d.z2));
  if (d.z2 < 0 && -d.z2 <= d.z1)
    throw InputError(w + "internal pair needs |z2| > z1, got z1 = " + std::to_string(d.z1) + ", z2 = " + std::to_string(d.z2));
  if (!(d.module_m > 0.0 && std::isfinite(d.module_m))) throw InputError(w + "module_m must be > 0 (m)");
  if (!(d.pressure_angle_rad > 0.1 && d.pressure_angle_rad < 0.6)) throw InputError(w + "pressure_angle_rad must be in (0.1, 0.6)");
  if (!(d.face_width_m > 0.0 && std::isfinite(d.face_width_m))) throw InputError(w + "face_width_m must be > 0 (m)");
  if (!(d.addendum_over_module > 0.0 && d.addendum_over_module < 2.0)) throw InputError(w + "addendum_over_module must be in (0, 2)");
  if (!(d.dedendum_over_module > d.addendum_over_module && d.dedendum_over_module < 2.5))
    throw InputError(w + "dedendum_over_module must be in (addendum_over_module, 2.5)");
  if (!(d.young_modulus_Pa > 0.0 && std::isfinite(d.young_modulus_Pa))) throw InputError(w + "young_modulus_Pa must be > 0 (Pa)");
  if (!(d.poisson_ratio >= 0.0 && d.poisson_ratio < 0.5)) throw InputError(w + "poisson_ratio must be in [0, 0.5)");
  if (!(d.rack_tip_radius_over_module >= 0.0 && d.rack_tip_radius_over_module < 0.5))
    throw InputError(w + "rack_tip_radius_over_module must be in [0, 0.5)");
  if (!(d.root_over_bore1 > 1.0 && d.root_over_bore2 > 1.0)) throw InputError(w + "root_over_bore1/2 (r_f / r_int) must be > 1");
}

// One gear's tooth as a cantilever. Local frame: y along the tooth centre line, away from the
// gear centre; x across the tooth, the loaded flank at x > 0. A flank point with roll angle
// t = tan α_r sits at radius r = r_b √(1 + t²) and polar angle ψ(t) = c0 + s (t − atan t) from the
// centre line: external tooth c0 = π/(2z) + inv α, s = −1; internal (ring) tooth = the space of
// the external gear, c0 = π/(2z) − inv α, s = +1.
struct Tooth {
  bool internal = false;
  double rb = 0, ra = 0, rf = 0;  // base, tip, root radii, in m
  double c0 = 0, s = 0;  // half angle at the base circle (rad), flank sign
  double y_root = 0;  // centre-line coordinate of the clamped section, in m
  double t_root = 0;  // roll angle where the involute part of the cantilever starts
  double h_uniform = 0;  // half thickness of the straight part below r_b (external, r_f < r_b), in m
  double y_base = 0;  // centre-line coordinate where that straight part ends, in m
  double theta_f = 0;  // half angle of the tooth at the root circle (fillets included), in rad
  double root_over_bore = 0;  // Sainsot's h_f
};

double psi(const Tooth& g, double t) { return g.c0 + g.s * (t - std::atan(t)); }
double radius(const Tooth& g, double t) { return g.rb * std::sqrt(1.0 + t * t); }
double roll_of(const Tooth& g, double r) { return std::sqrt(std::max(r * r - g.rb * g.rb, 0.0)) / g.rb; }

Tooth make_tooth(const PotentialEnergyPairDef& d, int z_signed, double root_over_bore) {
  Tooth g;
  g.internal = z_signed < 0;
  const int z = std::abs(z_signed);
  const double r = d.module_m * z / 2.0;
  const double ha = d.addendum_over_module * d.module_m, hf = d.dedendum_over_module * d.module_m;
  g.rb = r * std::cos(d.pressure_angle_rad);
  g.root_over_bore = root_over_bore;
  const double inv0 = involute(d.pressure_angle_rad);
  // Half angle of the tooth at the root circle, fillets included: the generating rack's space
  // width where its tip rounding meets its tip line, π/2 + 2 tan α (h_f − ρ) + 2 ρ / cos α (in
  // modules), over the pitch radius (the tip line rolls on the root circle as the pitch line on
  // the pitch circle). The ring tooth, a shaper-cut space, takes the same form by analogy.
  const double rho = d.rack_tip_radius_over_module, ta = std::tan(d.pressure_angle_rad);
  g.theta_f = (kPi / 2.0 + 2.0 * ta * (d.dedendum_over_module - rho) + 2.0 * rho / std::cos(d.pressure_angle_rad)) / z;
  if (!g.internal) {
    g.ra = r + ha;
    g.rf = r - hf;
    g.c0 = kPi / (2.0 * z) + inv0;
    g.s = -1.0;
    if (g.rf < g.rb) {
      // Clamped on the root circle with a straight section of the base-circle thickness up to
      // the base circle (Chen & Shao 2011); the root fillet's extra thickness is neglected.
      g.h_uniform = g.rb * std::sin(g.c0);
      g.y_base = g.rb * std::cos(g.c0);
      g.y_root = std::sqrt(g.rf * g.rf - g.h_uniform * g.h_uniform);
      g.t_root = 0.0;
    } else {
      // Clamped on the root circle, inside the involute.
      g.t_root = roll_of(g, g.rf);
      g.y_root = g.y_base = g.rf * std::cos(psi(g, g.t_root));
    }
  } else {
    g.ra = r - ha;
    g.rf = r + hf;
    g.c0 = kPi / (2.0 * z) - inv0;
    g.s = 1.0;
    // The ring tooth's flank is the involute up to its root circle (shaper-cut, fillet neglected).
    g.t_root = roll_of(g, g.rf);
    g.y_root = g.y_base = g.rf * std::cos(psi(g, g.t_root));
  }
  return g;
}

// Gauss–Legendre nodes and weights on [−1, 1], 5 points.
constexpr std::array<double, 5> kGlX = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kGlW = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};

// ∫_a^b f(u) du by composite Gauss–Legendre.
template <class F>
double integrate(double a, double b, F f) {
  const double h = (b - a) / kPeQuadraturePanels;
  double sum = 0.0;
  for (int p = 0; p < kPeQuadraturePanels; ++p) {
    const double mid = a + (p + 0.5) * h;
    for (int i = 0; i < 5; ++i) sum += kGlW[i] * f(mid + 0.5 * h * kGlX[i]);
  }
  return 0.5 * h * sum;
}

// Compliances of tooth g loaded at roll angle t_c by a unit force along the line of action.
ToothCompliance tooth_compliance(const PotentialEnergyPairDef& d, const Tooth& g, double t_c) {
  const double E = d.young_modulus_Pa, b = d.face_width_m;
  const double G = E / (2.0 * (1.0 + d.poisson_ratio));
  // Contact point P and the unit force f pressing into the tooth. The line of action is tangent
  // to the base circle; its angle to the centre line's normal is the load angle α_m.
  const double rc = radius(g, t_c), pc = psi(g, t_c), alpha_r = std::atan(t_c);
  const double px = rc * std::sin(pc), py = rc * std::cos(pc);
  const double alpha_m = g.internal ? pc + alpha_r : alpha_r - pc;
  const double fx = -std::cos(alpha_m);
  const double fy = g.internal ? std::sin(alpha_m) : -std::sin(alpha_m);  // towards the root
  // Energy densities per unit length of the centre line, for a section of half thickness h at y.
  auto density = [&](double y, double h, double& bend, double& shear, double& axial) {
    const double moment = px * fy - (py - y) * fx;  // N·m per N
    const double area = 2.0 * h * b, inertia = 2.0 * h * h * h * b / 3.0;
    bend = moment * moment / (E * inertia);
    shear = kPeShearCoefficient * fx * fx / (G * area);
    axial = fy * fy / (E * area);
  };
  ToothCompliance c;
  auto add = [&](double a, double bnd, auto section) {  // section(u) -> {y, h, |dy/du|}
    c.bending_m_per_N += integrate(a, bnd, [&](double u) {
      double y, h, j;
      section(u, y, h, j);
      double kb, ks, ka;
      density(y, h, kb, ks, ka);
      return kb * j;
    });
    c.shear_m_per_N += integrate(a, bnd, [&](double u) {
      double y, h, j;
      section(u, y, h, j);
      double kb, ks, ka;
      density(y, h, kb, ks, ka);
      return ks * j;
    });
    c.axial_m_per_N += integrate(a, bnd, [&](double u) {
      double y, h, j;
      section(u, y, h, j);
      double kb, ks, ka;
      density(y, h, kb, ks, ka);
      return ka * j;
    });
  };
  // Straight part below the base circle (external tooth with r_f < r_b).
  if (g.y_base > g.y_root) {
    add(g.y_root, g.y_base, [&](double y, double& yy, double& h, double& j) {
      yy = y;
      h = g.h_uniform;
      j = 1.0;
    });
  }
  // Involute part from the clamp (or the base circle) to the contact, parametrised by roll angle.
  add(std::min(g.t_root, t_c), std::max(g.t_root, t_c), [&](double t, double& y, double& h, double& j) {
    const double r = radius(g, t), p = psi(g, t);
    y = r * std::cos(p);
    h = r * std::sin(p);
    const double dr = g.rb * t / std::sqrt(1.0 + t * t), dp = g.s * t * t / (1.0 + t * t);
    j = std::abs(dr * std::cos(p) - r * std::sin(p) * dp);
  });
  // Fillet foundation, Sainsot et al. (2004): u_f from the root circle to where the line of
  // action crosses the centre line, S_f = 2 r_f θ_f the tooth thickness at the root circle.
  if (d.include_fillet_foundation) {
    const double y_cross = py - px * fy / fx;
    const double uf = g.internal ? g.rf - y_cross : y_cross - g.rf;
    const double sf = 2.0 * g.rf * g.theta_f;
    const double th = g.theta_f, hf = g.root_over_bore;
    auto poly = [&](double A, double B, double C, double D, double Ecoef, double F) {
      return A / (th * th) + B * hf * hf + C * hf / th + D / th + Ecoef * hf + F;
    };
    const double L = poly(-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045);
    const double M = poly(60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086);
    const double P = poly(-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236);
    const double Q = poly(-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904);
    const double ratio = uf / sf, tm = std::tan(alpha_m), cm = std::cos(alpha_m);
    c.foundation_m_per_N = cm * cm / (E * b) * (L * ratio * ratio + M * ratio + P * (1.0 + Q * tm * tm));
    GEARSIM_CHECK(c.foundation_m_per_N > 0.0, "Sainsot foundation compliance must be positive");
  }
  return c;
}

// Centre distance times sin α: the length between the two base tangent points, in m.
double tangent_span(const PotentialEnergyPairDef& d) {
  return d.module_m * (d.z1 + d.z2) / 2.0 * std::sin(d.pressure_angle_rad);  // z2 < 0: |z2| − z1 with sign
}

}  // namespace

double hertz_stiffness(const PotentialEnergyPairDef& d) {
  validate(d);
  const double nu = d.poisson_ratio;
  return kPi * d.young_modulus_Pa * d.face_width_m / (4.0 * (1.0 - nu * nu));
}

ContactPath contact_path(const PotentialEnergyPairDef& d) {
  validate(d);
  const Tooth p = make_tooth(d, d.z1, d.root_over_bore1), w = make_tooth(d, d.z2, d.root_over_bore2);
  const double span = std::abs(tangent_span(d));
  const double wheel_tip_roll = std::sqrt(std::max(w.ra * w.ra - w.rb * w.rb, 0.0));
  if (w.internal && w.ra <= w.rb)
    throw InputError("potential-energy stiffness: ring tip circle inside its base circle (|z2| too small for this pressure angle)");
  ContactPath c;
  c.pinion_base_radius_m = p.rb;
  c.base_pitch_m = kPi * d.module_m * std::cos(d.pressure_angle_rad);
  c.end_roll_m = std::sqrt(p.ra * p.ra - p.rb * p.rb);
  c.start_roll_m = w.internal ? wheel_tip_roll - span : span - wheel_tip_roll;
  // Contact must stay on both involutes above each cantilever's clamp.
  const double pinion_min_roll = std::max(p.t_root, 0.0) * p.rb;
  if (c.start_roll_m < pinion_min_roll)
    throw InputError("potential-energy stiffness: the wheel tip reaches below the pinion's involute (interference; z1 = " +
                     std::to_string(d.z1) + " too small)");
  const double wheel_end_roll = w.internal ? c.end_roll_m + span : span - c.end_roll_m;
  if (!w.internal && wheel_end_roll < std::max(w.t_root, 0.0) * w.rb)
    throw InputError("potential-energy stiffness: the pinion tip reaches below the wheel's involute (interference; z2 = " +
                     std::to_string(d.z2) + " too small)");
  c.contact_ratio = (c.end_roll_m - c.start_roll_m) / c.base_pitch_m;
  if (!(c.contact_ratio >= 1.0 && c.contact_ratio < kPeMaxPairsInContact))
    throw InputError("potential-energy stiffness: contact ratio " + std::to_string(c.contact_ratio) + " outside [1, 3)");
  return c;
}

PairCompliance single_pair_compliance(const PotentialEnergyPairDef& d, double r1) {
  const ContactPath path = contact_path(d);
  const Tooth p = make_tooth(d, d.z1, d.root_over_bore1), w = make_tooth(d, d.z2, d.root_over_bore2);
  const double roll1 = std::sqrt(std::max(r1 * r1 - p.rb * p.rb, 0.0));
  if (!(r1 >= p.rb && roll1 >= path.start_roll_m - kPeRollSlack_m && roll1 <= path.end_roll_m + kPeRollSlack_m))
    throw InputError("potential-energy stiffness: pinion_contact_radius_m " + std::to_string(r1) + " is off the path of contact");
  const double span = std::abs(tangent_span(d));
  const double roll2 = w.internal ? roll1 + span : span - roll1;
  PairCompliance c;
  c.pinion_contact_radius_m = r1;
  c.wheel_contact_radius_m = std::hypot(w.rb, roll2);
  c.pinion = tooth_compliance(d, p, roll1 / p.rb);
  c.wheel = tooth_compliance(d, w, roll2 / w.rb);
  c.hertz_m_per_N = 1.0 / hertz_stiffness(d);
  c.stiffness_N_per_m = 1.0 / (c.hertz_m_per_N + c.pinion.total_m_per_N() + c.wheel.total_m_per_N());
  return c;
}

double single_pair_stiffness(const PotentialEnergyPairDef& d, double r1) { return single_pair_compliance(d, r1).stiffness_N_per_m; }

std::vector<StiffnessSample> mesh_stiffness_curve(const PotentialEnergyPairDef& d, int n) {
  if (n < 10) throw InputError("potential-energy stiffness: samples_per_period must be >= 10, got " + std::to_string(n));
  const ContactPath path = contact_path(d);
  const double period_rad = 2.0 * kPi / d.z1;
  std::vector<StiffnessSample> out(n);
  for (int k = 0; k < n; ++k) {
    StiffnessSample& s = out[k];
    s.roll_angle_rad = period_rad * k / n;
    // Pair j trails the leading pair by j base pitches along the line of action.
    for (int j = 0; j < kPeMaxPairsInContact; ++j) {
      const double roll = path.start_roll_m + path.pinion_base_radius_m * s.roll_angle_rad + j * path.base_pitch_m;
      if (roll > path.end_roll_m + kPeRollSlack_m) break;
      const double r1 = std::hypot(path.pinion_base_radius_m, roll);
      s.pinion_contact_radius_m[s.pairs_in_contact] = r1;
      s.pair_stiffness_N_per_m[s.pairs_in_contact] = single_pair_stiffness(d, r1);
      s.mesh_stiffness_N_per_m += s.pair_stiffness_N_per_m[s.pairs_in_contact];
      ++s.pairs_in_contact;
    }
    GEARSIM_CHECK(s.pairs_in_contact >= 1, "a contact ratio >= 1 keeps a pair in contact");
  }
  return out;
}

StiffnessSummary summarize_mesh_stiffness(const PotentialEnergyPairDef& d, int n) {
  const std::vector<StiffnessSample> curve = mesh_stiffness_curve(d, n);
  StiffnessSummary s;
  s.min_N_per_m = curve.front().mesh_stiffness_N_per_m;
  s.max_N_per_m = s.min_N_per_m;
  double pairs = 0.0;
  for (const StiffnessSample& c : curve) {
    s.mean_N_per_m += c.mesh_stiffness_N_per_m / n;
    s.min_N_per_m = std::min(s.min_N_per_m, c.mesh_stiffness_N_per_m);
    s.max_N_per_m = std::max(s.max_N_per_m, c.mesh_stiffness_N_per_m);
    pairs += c.pairs_in_contact;
    for (int j = 0; j < c.pairs_in_contact; ++j)
      s.single_pair_max_N_per_m = std::max(s.single_pair_max_N_per_m, c.pair_stiffness_N_per_m[j]);
  }
  s.contact_ratio = pairs / n;
  s.mean_per_width_N_per_m2 = s.mean_N_per_m / d.face_width_m;
  return s;
}

}  // namespace gearsim::fe
