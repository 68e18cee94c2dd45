#include "fe/deck.hpp"

#include <Eigen/Geometry>
#include <cctype>
#include <cstdio>
#include <sstream>

#include "core/errors.hpp"
#include "fe/constants.hpp"

namespace gearsim::fe {
namespace {

// Numbers at full precision (the deck is read back only by ccx; %.12g keeps nm resolution in mm).
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

// A real number ccx reads as real in every card (some cards take "1000" for an integer).
std::string real(double v) {
  std::string s = num(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".";
  return s;
}

void check_name(const std::string& what, const std::string& name) {
  if (name.empty()) throw InputError(what + " name is empty");
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) throw InputError(what + " name '" + name + "' must be letters and digits only");
}

// Writes "a, b, c, …" in rows of at most 8 entries (ccx reads 16 per line).
void write_id_list(std::ostringstream& o, const std::vector<int>& ids) {
  for (size_t i = 0; i < ids.size(); ++i) o << ids[i] << ((i + 1) % 8 == 0 || i + 1 == ids.size() ? "\n" : ", ");
}

void validate(const DeckDef& def) {
  int driving = 0;
  for (const FeBody& b : def.bodies) {
    check_name("body", b.name);
    if (b.mesh.quads.empty()) throw InputError("body " + b.name + ": mesh has no elements");
    for (const auto& q : b.mesh.quads)
      for (int n : q)
        if (n < 0 || n >= static_cast<int>(b.mesh.nodes_m.size()))
          throw InputError("body " + b.name + ": element refers to a node that does not exist");
    if (b.support != FeSupport::Fixed && b.mesh.hub_nodes.empty())
      throw InputError("body " + b.name + ": a driving or idling body needs hub (bore) nodes");
    if (b.support == FeSupport::Fixed && b.mesh.fixed_nodes.empty())
      throw InputError("body " + b.name + ": a fixed body needs fixed (rim) nodes");
    if (b.support == FeSupport::Driving) ++driving;
  }
  if (driving != 1) throw InputError("deck needs exactly one driving body, got " + std::to_string(driving));
  for (const FeContact& c : def.contacts) {
    check_name("contact", c.name);
    const int nb = static_cast<int>(def.bodies.size());
    if (c.slave < 0 || c.slave >= nb || c.master < 0 || c.master >= nb || c.slave == c.master)
      throw InputError("contact " + c.name + ": slave and master must be two different bodies");
    if (c.slave_edges.empty() || c.master_edges.empty()) throw InputError("contact " + c.name + ": a surface has no edges");
  }
  if (!(def.young_modulus_Pa > 0) || !(def.poisson_ratio > -1 && def.poisson_ratio < 0.5))
    throw InputError("deck: E must be > 0 and −1 < ν < 0.5");
  if (!(def.thickness_m > 0)) throw InputError("deck: thickness_m must be > 0");
  if (!(def.friction >= 0)) throw InputError("deck: friction must be ≥ 0");
  if (!(def.idler_spring_N_m_per_rad >= 0) || !(def.driving_spring_N_m_per_rad >= 0))
    throw InputError("deck: idler_spring_N_m_per_rad and driving_spring_N_m_per_rad must be ≥ 0");
  if (!(def.contact_penalty_Pa_per_m > 0) || !(def.stick_slope_Pa_per_m > 0))
    throw InputError("deck: contact penalty and stick slope must be > 0");
  if (def.load_fractions.empty()) throw InputError("deck: needs at least one load stage");
  double prev = 0;
  for (double f : def.load_fractions) {
    if (!(f > prev)) throw InputError("deck: load_fractions must increase from above 0");
    prev = f;
  }
  for (const FeElementSet& es : def.stress_sets) {
    check_name("stress set", es.name);
    if (es.body < 0 || es.body >= static_cast<int>(def.bodies.size()))
      throw InputError("stress set " + es.name + ": body index out of range");
    if (es.elements.empty()) throw InputError("stress set " + es.name + ": no elements");
    for (int e : es.elements)
      if (e < 0 || e >= static_cast<int>(def.bodies[static_cast<size_t>(es.body)].mesh.quads.size()))
        throw InputError("stress set " + es.name + ": element " + std::to_string(e) + " is not in body " +
                         def.bodies[static_cast<size_t>(es.body)].name);
  }
  if (def.element_type != "CPS4R" && def.element_type != "CPS4")
    throw InputError("deck: element_type must be CPS4R or CPS4, got " + def.element_type);
}

}  // namespace

Deck write_deck(const DeckDef& def) {
  validate(def);
  const double L = kDeckLength_per_m;  // m → mm
  const double P = kDeckStress_per_Pa;  // Pa → MPa
  const double M = kDeckLength_per_m;  // N·m → N·mm
  Deck deck;
  std::ostringstream o;
  o << "** Gearsim plane-stress contact deck. Units: mm, N, MPa.\n";

  // Layout: mesh nodes and elements body after body, then centre and rotation nodes.
  int next_node = 1, next_el = 1;
  for (const FeBody& b : def.bodies) {
    deck.layout.push_back({next_node, next_el, 0, 0});
    next_node += static_cast<int>(b.mesh.nodes_m.size());
    next_el += static_cast<int>(b.mesh.quads.size());
  }
  for (auto& l : deck.layout) {
    l.centre_node = next_node++;
    l.rotation_node = next_node++;
  }

  // Nodes, placed.
  o << "*NODE, NSET=NALL\n";
  std::vector<std::vector<Eigen::Vector2d>> placed(def.bodies.size());
  for (size_t bi = 0; bi < def.bodies.size(); ++bi) {
    const FeBody& b = def.bodies[bi];
    const Eigen::Rotation2Dd rot(b.angle_rad);
    for (size_t i = 0; i < b.mesh.nodes_m.size(); ++i) {
      const Eigen::Vector2d p = b.centre_m + rot * b.mesh.nodes_m[i];
      placed[bi].push_back(p);
      o << deck.layout[bi].first_node + static_cast<int>(i) << ", " << num(p.x() * L) << ", " << num(p.y() * L) << ", 0\n";
    }
  }
  for (size_t bi = 0; bi < def.bodies.size(); ++bi) {
    const Eigen::Vector2d c = def.bodies[bi].centre_m * L;
    o << deck.layout[bi].centre_node << ", " << num(c.x()) << ", " << num(c.y()) << ", 0\n";
    o << deck.layout[bi].rotation_node << ", " << num(c.x()) << ", " << num(c.y()) << ", 0\n";
  }

  // Elements and sections, one element set per body.
  o << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << num(def.young_modulus_Pa * P) << ", " << num(def.poisson_ratio) << "\n";
  for (size_t bi = 0; bi < def.bodies.size(); ++bi) {
    const FeBody& b = def.bodies[bi];
    o << "*ELEMENT, TYPE=" << def.element_type << ", ELSET=E" << b.name << "\n";
    for (size_t e = 0; e < b.mesh.quads.size(); ++e) {
      o << deck.layout[bi].first_element + static_cast<int>(e);
      for (int n : b.mesh.quads[e]) o << ", " << deck.layout[bi].first_node + n;
      o << "\n";
    }
    o << "*SOLID SECTION, ELSET=E" << b.name << ", MATERIAL=STEEL\n" << num(def.thickness_m * L) << "\n";
  }

  // Node sets: centres, rotation nodes, fixed rims.
  std::vector<int> centres, rotations, fixed;
  for (size_t bi = 0; bi < def.bodies.size(); ++bi) {
    centres.push_back(deck.layout[bi].centre_node);
    rotations.push_back(deck.layout[bi].rotation_node);
    for (int n : def.bodies[bi].mesh.fixed_nodes) fixed.push_back(deck.layout[bi].first_node + n);
  }
  o << "*NSET, NSET=NCENTRE\n";
  write_id_list(o, centres);
  o << "*NSET, NSET=NROT\n";
  write_id_list(o, rotations);
  if (!fixed.empty()) {
    o << "*NSET, NSET=NFIXED\n";
    write_id_list(o, fixed);
  }

  // Element sets whose stresses are printed.
  for (const FeElementSet& es : def.stress_sets) {
    o << "*ELSET, ELSET=" << es.name << "\n";
    std::vector<int> ids;
    for (int e : es.elements) ids.push_back(deck.layout[static_cast<size_t>(es.body)].first_element + e);
    write_id_list(o, ids);
  }

  // Rigid hubs, linearised: u_i − u_C + (y_i − y_C)·θ = 0, v_i − v_C − (x_i − x_C)·θ = 0.
  for (size_t bi = 0; bi < def.bodies.size(); ++bi) {
    const FeBody& b = def.bodies[bi];
    if (b.support == FeSupport::Fixed) continue;
    const FeBodyLayout& l = deck.layout[bi];
    o << "*EQUATION\n";
    for (int n : b.mesh.hub_nodes) {
      const Eigen::Vector2d d = (placed[bi][n] - b.centre_m) * L;
      const int id = l.first_node + n;
      o << "3\n" << id << ", 1, 1., " << l.centre_node << ", 1, -1., " << l.rotation_node << ", 1, " << num(d.y()) << "\n";
      o << "3\n" << id << ", 2, 1., " << l.centre_node << ", 2, -1., " << l.rotation_node << ", 1, " << num(-d.x()) << "\n";
    }
  }

  // Weak rotational springs on idlers (SPRING1 on the rotation node's dof 1).
  std::vector<int> idler_rot;
  for (size_t bi = 0; bi < def.bodies.size(); ++bi)
    if (def.bodies[bi].support == FeSupport::Idler) idler_rot.push_back(deck.layout[bi].rotation_node);
  if (!idler_rot.empty() && def.idler_spring_N_m_per_rad > 0) {
    o << "*ELEMENT, TYPE=SPRING1, ELSET=ESPRING\n";
    for (int n : idler_rot) o << next_el++ << ", " << n << "\n";
    o << "*SPRING, ELSET=ESPRING\n1\n" << real(def.idler_spring_N_m_per_rad * M) << "\n";
  }
  // The driving body's spring (SPRING1 on its rotation node's dof 1).
  if (def.driving_spring_N_m_per_rad > 0) {
    o << "*ELEMENT, TYPE=SPRING1, ELSET=EDRIVESPRING\n";
    for (size_t bi = 0; bi < def.bodies.size(); ++bi)
      if (def.bodies[bi].support == FeSupport::Driving) o << next_el++ << ", " << deck.layout[bi].rotation_node << "\n";
    o << "*SPRING, ELSET=EDRIVESPRING\n1\n" << real(def.driving_spring_N_m_per_rad * M) << "\n";
  }

  // Contact surfaces and pairs.
  auto surface = [&](const std::string& name, int bi, const std::vector<std::pair<int, int>>& edges) {
    o << "*SURFACE, NAME=" << name << "\n";
    for (const auto& [q, e] : edges) {
      if (q < 0 || q >= static_cast<int>(def.bodies[bi].mesh.quads.size()) || e < 0 || e > 3)
        throw InputError("contact surface " + name + ": edge (" + std::to_string(q) + ", " + std::to_string(e) +
                         ") is not an edge of body " + def.bodies[bi].name);
      o << deck.layout[bi].first_element + q << ", S" << e + 1 << "\n";
    }
  };
  if (!def.contacts.empty())
    o << "*SURFACE INTERACTION, NAME=FLANKS\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
      << num(def.contact_penalty_Pa_per_m * P / L) << ", " << num(kOpenContactTension_Pa * P) << "\n";
  if (def.friction > 0 && !def.contacts.empty())
    o << "*FRICTION\n" << num(def.friction) << ", " << num(def.stick_slope_Pa_per_m * P / L) << "\n";
  for (const FeContact& c : def.contacts) {
    surface("S" + c.name, c.slave, c.slave_edges);
    surface("M" + c.name, c.master, c.master_edges);
    o << "*CONTACT PAIR, INTERACTION=FLANKS, TYPE=SURFACE TO SURFACE\nS" << c.name << ", M" << c.name << "\n";
  }

  // Supports common to every step: centres held, rotation nodes turn about z only, rims held.
  int driving_rot = 0;
  for (size_t bi = 0; bi < def.bodies.size(); ++bi)
    if (def.bodies[bi].support == FeSupport::Driving) driving_rot = deck.layout[bi].rotation_node;
  auto supports = [&](bool new_op) {
    o << (new_op ? "*BOUNDARY, OP=NEW\n" : "*BOUNDARY\n") << "NCENTRE, 1, 3\nNROT, 2, 3\n";
    if (!fixed.empty()) o << "NFIXED, 1, 2\n";
    for (size_t bi = 0; bi < def.bodies.size(); ++bi)
      if (def.bodies[bi].support == FeSupport::Fixed) o << deck.layout[bi].rotation_node << ", 1, 1\n";
  };
  auto prints = [&] {
    o << "*NODE PRINT, NSET=NROT\nU\n*NODE PRINT, NSET=NCENTRE\nRF\n";
    for (const FeContact& c : def.contacts) o << "*CONTACT PRINT, SLAVE=S" << c.name << ", MASTER=M" << c.name << "\nCF\n";
    for (const FeElementSet& es : def.stress_sets) o << "*EL PRINT, ELSET=" << es.name << "\nS\n";
  };

  // Step 1: the driving body turned by closing_rotation_rad closes the contacts.
  supports(false);
  o << "*STEP, INC=" << kStepMaxIncrements << "\n*STATIC\n"
    << num(kFirstIncrement) << ", 1, " << num(kMinIncrement) << ", " << num(kMaxIncrement) << "\n*BOUNDARY\n"
    << driving_rot << ", 1, 1, " << num(def.closing_rotation_rad) << "\n";
  prints();
  o << "*END STEP\n";

  // Steps 2…: rotation released, torque stages.
  for (double f : def.load_fractions) {
    o << "*STEP, INC=" << kStepMaxIncrements << "\n*STATIC\n"
      << num(kFirstIncrement) << ", 1, " << num(kMinIncrement) << ", " << num(kMaxIncrement) << "\n";
    supports(true);
    o << "*CLOAD, OP=NEW\n" << driving_rot << ", 1, " << num(f * def.torque_N_m * M) << "\n";
    prints();
    o << "*END STEP\n";
  }
  deck.steps = 1 + static_cast<int>(def.load_fractions.size());
  deck.text = o.str();
  return deck;
}

}  // namespace gearsim::fe
