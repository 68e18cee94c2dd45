#include "fe/spur_pair_fe.hpp"

#include <cmath>
#include <fstream>
#include <numbers>

#include "core/errors.hpp"
#include "geometry/gear_profile.hpp"
#include "fe/ccx_dat.hpp"
#include "fe/deck.hpp"
#include "fe/iso6336_stiffness.hpp"
#include "fe/process.hpp"
#include "core/output_file.hpp"

namespace gearsim::fe {
namespace {

// Samples per mesh period of the potential-energy mean (as docs/fe-results.md's PE table: 400).
constexpr int kPeSamplesPerPeriod = 400;

// The pinion's rotation (dof 1 of its rotation node) at the end of the step ending at `time`.
double rotation_at(const std::vector<DatBlock>& blocks, int rotation_node, double time, const std::filesystem::path& dat) {
  for (const DatBlock& b : blocks)
    if (b.quantity == "displacements" && b.set == "NROT" && std::abs(b.time - time) < 1e-6) return b.rows.at(rotation_node).at(0);
  throw std::runtime_error(std::string("ccx results lack the rotations at time ") + std::to_string(time) + " (" + dat.string() + ")");
}

// Total contact force of one pair at `time` (the last increment printed then), N; zero vector when
// ccx printed no statistics for it (no active contact).
Eigen::Vector2d pair_force(const std::vector<ContactTotals>& totals, const std::string& slave, double time) {
  for (auto it = totals.rbegin(); it != totals.rend(); ++it)
    if (it->slave == slave && std::abs(it->time - time) < 1e-6) return {it->force[0], it->force[1]};
  return Eigen::Vector2d::Zero();
}

std::vector<int> loop_nodes(const QuadMesh2& m) {
  std::vector<int> out;
  for (const QuadEdge& e : m.toothed_edges) out.push_back(m.quads[static_cast<size_t>(e.first)][static_cast<size_t>(e.second)]);
  return out;
}

FeMesh fe_mesh(const QuadMesh2& q) {
  FeMesh m;
  m.nodes_m = q.nodes;
  m.quads = q.quads;
  m.boundary_edges = q.toothed_edges;
  return m;
}

}  // namespace

void validate_spur_pair_fe(const SpurPairFeDef& d) {
  validate_spur_pair(d.pair);
  const std::string w = "spur pair FE: ";
  if (!(d.pinion_torque_N_m > 0 && std::isfinite(d.pinion_torque_N_m)))
    throw InputError(w + "pinion_torque_N_m must be > 0 (N·m), got " + std::to_string(d.pinion_torque_N_m));
  if (!(d.low_load_fraction > 0 && d.low_load_fraction < 1))
    throw InputError(w + "low_load_fraction must be in (0, 1), got " + std::to_string(d.low_load_fraction));
  if (!(d.friction >= 0 && d.friction < 1)) throw InputError(w + "friction must be in [0, 1), got " + std::to_string(d.friction));
  if (d.element_type != "CPS4R" && d.element_type != "CPS4")
    throw InputError(w + "element_type must be CPS4R or CPS4, got " + d.element_type);
}

SpurPairMeshes mesh_spur_pair(const SpurPairFeDef& def) {
  validate_spur_pair_fe(def);
  return {mesh_gear_outline(make_gear_outline(pinion_spec(def.pair)), GearKind::External, def.sizing),
          mesh_gear_outline(make_gear_outline(wheel_spec(def.pair)), GearKind::External, def.sizing)};
}

SpurPairFePosition solve_spur_pair_position(const SpurPairFeDef& def, const SpurPairMeshes& meshes, double roll_m,
                                            const std::filesystem::path& work_dir) {
  validate_spur_pair_fe(def);
  const SpurPairDef& pd = def.pair;
  const SpurPairPath path = spur_pair_path(pd);
  const SpurPairPlacement place = place_spur_pair(pd, meshes.pinion.mesh, meshes.wheel.mesh, roll_m);
  const QuadMesh2 &pm = meshes.pinion.mesh, &wm = meshes.wheel.mesh;

  // Bodies: the pinion drives through its rigid hub, the wheel's bore is held.
  DeckDef deck;
  FeMesh pinion = fe_mesh(pm), wheel = fe_mesh(wm);
  pinion.hub_nodes = pm.bore_nodes;
  wheel.fixed_nodes = wm.bore_nodes;
  deck.bodies.push_back({"PINION", pinion, place.pinion.centre_m, place.pinion.angle_rad, FeSupport::Driving});
  deck.bodies.push_back({"WHEEL", wheel, place.wheel.centre_m, place.wheel.angle_rad, FeSupport::Fixed});
  // One contact pair per pinion tooth near the path (slave) and the wheel space it sits in.
  for (size_t i = 0; i < place.slots.size(); ++i)
    // std::string("…") + …, not "…" + a temporary: GCC 12 warns (-Wrestrict) on that form, wrongly.
    deck.contacts.push_back({std::string("C") + std::to_string(i), 0, 1, place.slots[i].pinion_edges, place.slots[i].wheel_edges});
  deck.young_modulus_Pa = kYoungModulus_Pa;
  deck.poisson_ratio = kPoissonRatio;
  deck.thickness_m = pd.face_width_m;
  deck.element_type = def.element_type;
  deck.friction = def.friction;
  deck.closing_rotation_rad = kClosingPress_m / path.pinion_base_radius_m;
  deck.torque_N_m = def.pinion_torque_N_m;
  deck.load_fractions = {def.low_load_fraction, 1.0};
  deck.driving_spring_N_m_per_rad = kSpurPinionSpring_N_m_per_rad;
  const Deck d = write_deck(deck);

  // Solve.
  std::filesystem::create_directories(work_dir);
  write_output_file(work_dir / "position.inp", d.text);
  const CcxRunResult run = run_ccx({def.ccx, work_dir, "position"});

  // Results at the end of the low (time 2) and full (time 3) load stages.
  const auto blocks = read_dat(run.dat_path);
  const auto totals = read_contact_totals(run.dat_path);
  SpurPairFePosition out;
  out.roll_m = roll_m;
  out.wheel_closing_exact_rad = place.wheel_closing_exact_rad;
  out.wheel_closing_fe_rad = place.wheel_closing_fe_rad;
  const int rot = d.layout[0].rotation_node;
  out.pinion_rotation_low_rad = rotation_at(blocks, rot, 2.0, run.dat_path);
  out.pinion_rotation_full_rad = rotation_at(blocks, rot, 3.0, run.dat_path);
  // The mesh carries the applied torque less the pinion spring's.
  out.torque_low_N_m = def.low_load_fraction * def.pinion_torque_N_m - kSpurPinionSpring_N_m_per_rad * out.pinion_rotation_low_rad;
  out.torque_full_N_m = def.pinion_torque_N_m - kSpurPinionSpring_N_m_per_rad * out.pinion_rotation_full_rad;
  Eigen::Vector2d low = Eigen::Vector2d::Zero(), full = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < place.slots.size(); ++i) {
    const SpurToothSlot& s = place.slots[i];
    const std::string slave = std::string("SC") + std::to_string(i);
    const Eigen::Vector2d fl = pair_force(totals, slave, 2.0), ff = pair_force(totals, slave, 3.0);
    low += fl;
    full += ff;
    out.pairs.push_back({s.pinion_tooth, s.roll_m, s.on_path, s.fe_gap_m, fl.norm(), ff.norm()});
  }
  out.contact_force_low_N = low.norm();
  out.contact_force_full_N = full.norm();
  if (!(out.contact_force_full_N > 0))
    throw std::runtime_error(std::string("ccx reports no contact force at full load (") + run.dat_path.string() + ")");
  for (const SpurPairFePairLoad& p : out.pairs)
    if (p.force_full_N > kLoadedPairShare * out.contact_force_full_N) ++out.loaded_pairs;
  const double rb1 = path.pinion_base_radius_m;
  out.stiffness_N_per_m =
      (out.torque_full_N_m - out.torque_low_N_m) / (rb1 * rb1 * (out.pinion_rotation_full_rad - out.pinion_rotation_low_rad));
  out.stiffness_per_width_N_per_m2 = out.stiffness_N_per_m / pd.face_width_m;
  // The potential-energy model at the same contact points.
  const PotentialEnergyPairDef pe = potential_energy_def(pd);
  for (const SpurPairFePairLoad& p : out.pairs)
    if (p.on_path) {
      out.pe_stiffness_N_per_m += single_pair_stiffness(pe, std::hypot(rb1, p.roll_m));
      ++out.pe_pairs;
    }
  out.wall_time_s = run.wall_time_s;
  return out;
}

GearBodyTorsion solve_gear_body_torsion(const SpurPairFeDef& def, const SpurPairMeshes& meshes, bool pinion,
                                        const std::filesystem::path& work_dir) {
  validate_spur_pair_fe(def);
  const QuadMesh2& q = pinion ? meshes.pinion.mesh : meshes.wheel.mesh;
  const GearDimensions dims = gear_dimensions(pinion ? pinion_spec(def.pair) : wheel_spec(def.pair));
  // The hub turned by the torque the gear carries in the pair, every toothed-loop node held.
  DeckDef deck;
  FeMesh m = fe_mesh(q);
  m.hub_nodes = q.bore_nodes;
  m.fixed_nodes = loop_nodes(q);
  deck.bodies.push_back({"BODY", m, Eigen::Vector2d::Zero(), 0.0, FeSupport::Driving});
  deck.young_modulus_Pa = kYoungModulus_Pa;
  deck.poisson_ratio = kPoissonRatio;
  deck.thickness_m = def.pair.face_width_m;
  deck.element_type = def.element_type;
  const double torque = def.pinion_torque_N_m * (pinion ? 1.0 : double(def.pair.wheel_teeth) / def.pair.pinion_teeth);
  deck.torque_N_m = torque;
  deck.load_fractions = {1.0};
  const Deck d = write_deck(deck);
  std::filesystem::create_directories(work_dir);
  write_output_file(work_dir / "torsion.inp", d.text);
  const CcxRunResult run = run_ccx({def.ccx, work_dir, "torsion"});
  GearBodyTorsion out;
  out.rotation_per_torque_rad_per_N_m = rotation_at(read_dat(run.dat_path), d.layout[0].rotation_node, 2.0, run.dat_path) / torque;
  out.line_of_action_compliance_m_per_N = dims.base_radius_m * dims.base_radius_m * out.rotation_per_torque_rad_per_N_m;
  const double shear_modulus_Pa = kYoungModulus_Pa / (2.0 * (1.0 + kPoissonRatio));
  const double r_bore = 0.5 * def.pair.bore_over_root * 2.0 * dims.root_radius_m;
  out.annulus_closed_form_rad_per_N_m = (1.0 / (r_bore * r_bore) - 1.0 / (dims.root_radius_m * dims.root_radius_m)) /
                                        (4.0 * std::numbers::pi * shear_modulus_Pa * def.pair.face_width_m);
  out.wall_time_s = run.wall_time_s;
  return out;
}

double stiffness_without_body_torsion(double k, const GearBodyTorsion& p, const GearBodyTorsion& w) {
  const double c = 1.0 / k - p.line_of_action_compliance_m_per_N - w.line_of_action_compliance_m_per_N;
  GEARSIM_CHECK(c > 0, "body torsion compliance exceeds the mesh compliance");
  return 1.0 / c;
}

PotentialEnergyPairDef potential_energy_def(const SpurPairDef& pair) {
  validate_spur_pair(pair);
  PotentialEnergyPairDef pe;
  pe.z1 = pair.pinion_teeth;
  pe.z2 = pair.wheel_teeth;
  pe.module_m = pair.module_m;
  pe.pressure_angle_rad = pair.pressure_angle_rad;
  pe.face_width_m = pair.face_width_m;
  pe.root_over_bore1 = pe.root_over_bore2 = 1.0 / pair.bore_over_root;
  return pe;
}

SpurPairReferences spur_pair_references(const SpurPairDef& pair) {
  const PotentialEnergyPairDef pe = potential_energy_def(pair);
  const SpurPairPath path = spur_pair_path(pair);
  IsoPairDef iso;
  iso.z1 = pair.pinion_teeth;
  iso.z2 = pair.wheel_teeth;
  iso.pressure_angle_rad = pair.pressure_angle_rad;
  iso.contact_ratio = path.contact_ratio;
  SpurPairReferences r;
  r.contact_ratio = path.contact_ratio;
  r.iso_single_N_per_m2 = iso_single_stiffness(iso);
  r.iso_single_theory_N_per_m2 = iso_theoretical_single_stiffness(iso);
  r.iso_mesh_N_per_m2 = iso_mesh_stiffness(iso);
  r.iso_mesh_theory_N_per_m2 = r.iso_single_theory_N_per_m2 * (0.75 * path.contact_ratio + 0.25);
  r.pe_mean_N_per_m2 = summarize_mesh_stiffness(pe, kPeSamplesPerPeriod).mean_N_per_m / pair.face_width_m;
  r.pe_pitch_point_N_per_m2 = single_pair_stiffness(pe, std::hypot(path.pinion_base_radius_m, path.pitch_roll_m)) / pair.face_width_m;
  return r;
}

}  // namespace gearsim::fe
