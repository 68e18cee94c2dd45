#include "linear/modes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>

#include "core/errors.hpp"
#include "geometry/constants.hpp"

namespace gearsim::linear {
namespace {

// Eigenvalues below this fraction of the largest are rigid-body modes (ω = 0).
constexpr double kRigidFraction = 1e-10;
// Frequencies this close (relative) are one natural frequency repeated.
constexpr double kRepeatFraction = 1e-7;
// A body moves in a mode when its kinetic measure (√m·|u|, √I·|θ|) exceeds this fraction of the
// largest. Exact structures give zeros to rounding (1e-12); CAD gears, whose centres of mass sit
// microns off their axes and whose meshes differ by their facets, move the "still" members by
// 1e-5…1e-4 of the rest: 1e-3 calls a mode by what it is, not by its CAD noise.
constexpr double kStillFraction = 1e-3;

// Coordinates the constraints leave free: an orthonormal basis of C's null space.
Eigen::MatrixXd free_basis(const Eigen::MatrixXd& C, int n) {
  if (C.rows() == 0) return Eigen::MatrixXd::Identity(n, n);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i) rank += sv(i) > 1e-10 * sv(0);
  return svd.matrixV().rightCols(n - rank);
}

bool is_planet(const LumpedModel& m, const BodyInfo& b) { return b.parent >= 0 && m.bodies[b.parent].first_dof >= 0; }

ModeType classify(const LumpedModel& m, const Eigen::VectorXd& phi, bool& planets_alike) {
  double scale = 0;
  auto trans = [&](const BodyInfo& b) { return std::sqrt(b.mass_kg) * phi.segment<2>(b.first_dof).norm(); };
  auto rot = [&](const BodyInfo& b) { return std::sqrt(b.inertia_z_kg_m2) * std::abs(phi(b.first_dof + 2)); };
  bool planets = false;
  for (const BodyInfo& b : m.bodies)
    if (b.first_dof >= 0) scale = std::max({scale, trans(b), rot(b)}), planets = planets || is_planet(m, b);
  const double eps = kStillFraction * scale;
  bool central_translate = false, central_turn = false;
  for (const BodyInfo& b : m.bodies) {
    if (b.first_dof < 0 || is_planet(m, b)) continue;
    central_translate = central_translate || trans(b) > eps;
    central_turn = central_turn || rot(b) > eps;
  }
  // Each planet's motion in its own radial / tangential frame about its carrier.
  planets_alike = planets;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  bool have_first = false;
  for (const BodyInfo& b : m.bodies) {
    if (b.first_dof < 0 || !is_planet(m, b)) continue;
    const Eigen::Vector2d er = (b.centre_of_mass_m - m.bodies[b.parent].centre_of_mass_m).normalized();
    const Eigen::Vector2d et(-er.y(), er.x());
    const Eigen::Vector2d u = phi.segment<2>(b.first_dof);
    const Eigen::Vector3d local(std::sqrt(b.mass_kg) * u.dot(er), std::sqrt(b.mass_kg) * u.dot(et),
                                std::sqrt(b.inertia_z_kg_m2) * phi(b.first_dof + 2));
    if (!have_first)
      first = local, have_first = true;
    else
      planets_alike = planets_alike && (local - first).norm() <= eps;
  }
  if (planets && !central_translate && !central_turn) return ModeType::Planet;
  if (!central_translate) return ModeType::Rotational;
  if (!central_turn) return ModeType::Translational;
  return ModeType::Mixed;
}

}  // namespace

const char* to_string(ModeType t) {
  switch (t) {
    case ModeType::Rigid:
      return "rigid";
    case ModeType::Rotational:
      return "rotational";
    case ModeType::Translational:
      return "translational";
    case ModeType::Planet:
      return "planet";
    case ModeType::Mixed:
      return "mixed";
  }
  return "mixed";
}

ModalAnalysis solve_modes(const LumpedModel& m) {
  const int n = m.dofs();
  ModalAnalysis out;
  if (n == 0) return out;
  const Eigen::MatrixXd N = free_basis(m.constraints, n);
  out.free_coordinates = static_cast<int>(N.cols());
  if (N.cols() == 0) return out;
  const Eigen::MatrixXd K = N.transpose() * m.stiffness * N;
  const Eigen::MatrixXd M = N.transpose() * m.mass * N;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(0.5 * (K + K.transpose()), 0.5 * (M + M.transpose()));
  if (es.info() != Eigen::Success) throw InternalError("modes: the eigenproblem did not converge (is every free coordinate given a mass?)");
  const Eigen::VectorXd& lambda = es.eigenvalues();
  const double top = std::max(lambda.maxCoeff(), 0.0);
  for (int i = 0; i < lambda.size(); ++i) {
    Mode md;
    const bool rigid = !(lambda(i) > kRigidFraction * top);
    md.frequency_hz = rigid ? 0.0 : std::sqrt(lambda(i)) / (2 * constants::kPi);
    md.shape = N * es.eigenvectors().col(i);
    if (rigid) {
      md.type = ModeType::Rigid;
    } else {
      md.type = classify(m, md.shape, md.planets_alike);
      const double total = md.shape.dot(m.stiffness * md.shape);
      for (const Element& e : m.elements) md.energy_share.push_back(md.shape.dot(e.stiffness * md.shape) / total);
    }
    out.modes.push_back(std::move(md));
  }
  for (std::size_t i = 0; i < out.modes.size(); ++i) {
    Mode& md = out.modes[i];
    const bool joins = !out.groups.empty() &&
                       (out.groups.back().frequency_hz == 0 ? md.frequency_hz == 0
                                                            : md.frequency_hz - out.modes[out.groups.back().modes.back()].frequency_hz <=
                                                                  kRepeatFraction * md.frequency_hz);
    if (!joins) out.groups.push_back({md.frequency_hz, 0, md.type, {}});
    ModeGroup& g = out.groups.back();
    if (g.type != md.type) g.type = ModeType::Mixed;
    g.modes.push_back(static_cast<int>(i));
    g.multiplicity = static_cast<int>(g.modes.size());
    double sum = 0;
    for (int k : g.modes) sum += out.modes[static_cast<std::size_t>(k)].frequency_hz;
    g.frequency_hz = sum / g.multiplicity;
    md.group = static_cast<int>(out.groups.size()) - 1;
  }
  return out;
}

}  // namespace gearsim::linear
