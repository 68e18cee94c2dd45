// CalculiX input deck for planar bodies in contact: plane-stress quadrilateral meshes placed in
// one plane, each body rigidly coupled at its hub (bore) to a centre node and a rotation node,
// contact pairs with friction, and a quasi-static load sequence (a small imposed rotation of the
// driving body to close the contacts, then its torque in load stages).
// Not a mesher (gear_mesher makes the meshes) and not a result reader (ccx_dat reads them).
//
// SI at this interface. Inside the deck the units are mm, N, MPa (kDeckLength_per_m): contact
// search and penalty values in ccx behave best at that scale. The rigid coupling is linear
// (small rotations: each deck is one quasi-static position, rotations stay below ~1e-2 rad).
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace gearsim::fe {

// A planar quadrilateral mesh in its body frame.
struct FeMesh {
  std::vector<Eigen::Vector2d> nodes_m;  // m
  std::vector<std::array<int, 4>> quads;  // 0-based node indices, counter-clockwise
  std::vector<int> hub_nodes;  // coupled to the body's centre (bore), or empty
  std::vector<int> fixed_nodes;  // held in the plane (a fixed ring's rim, a test's clamp)
  std::vector<std::pair<int, int>> boundary_edges;  // (quad, local edge e: node e → e+1 mod 4)
};

// How a body is held.
enum class FeSupport {
  Driving,  // centre fixed, rotation free: carries the input torque
  Idler,  // centre fixed (a pin on a held carrier), rotation free
  Fixed,  // its fixed_nodes are held (a fixed ring)
};

struct FeBody {
  std::string name;  // letters and digits; becomes ccx set names
  FeMesh mesh;
  Eigen::Vector2d centre_m = Eigen::Vector2d::Zero();  // placement of the body frame's origin
  double angle_rad = 0;  // rotation of the body frame about +z
  FeSupport support = FeSupport::Idler;
};

// A contact pair: edges of the slave body against edges of the master body (both from the
// bodies' boundary_edges).
struct FeContact {
  std::string name;  // letters and digits
  int slave = 0, master = 0;  // body indices
  std::vector<std::pair<int, int>> slave_edges, master_edges;
};

// Elements of one body whose stresses are printed (*EL PRINT S) at the end of every step.
struct FeElementSet {
  std::string name;  // letters and digits; the ccx element set's name
  int body = 0;  // body index
  std::vector<int> elements;  // quad indices of that body's mesh
};

struct DeckDef {
  std::vector<FeBody> bodies;  // exactly one Driving body
  std::vector<FeContact> contacts;
  double young_modulus_Pa = 210e9;  // normally 210 GPa (steel)
  double poisson_ratio = 0.3;  // normally 0.3
  double thickness_m = 10e-3;  // face width (plane-stress thickness)
  std::string element_type = "CPS4R";  // CPS4R (paper), CPS4 or CPS4I-like full integration
  double friction = 0.03;  // Coulomb coefficient on the flanks (paper: 0.03)
  double contact_penalty_Pa_per_m = 1e16;  // normal penalty slope (pressure per overclosure)
  double stick_slope_Pa_per_m = 1e15;  // tangential stick stiffness (pressure per slip)
  double closing_rotation_rad = 0;  // step 1: imposed rotation of the driving body, rad
  double torque_N_m = 0;  // input torque on the driving body about +z
  std::vector<double> load_fractions = {0.1, 1.0};  // torque stages after step 1, increasing
  double idler_spring_N_m_per_rad = 0;  // weak rotational spring on idlers (keeps free rotation
      // of a body without contact from making K singular)
  // Weak rotational spring on the driving body, N·m/rad (0: none). It carries spring·θ of the
  // torque, which the caller subtracts; it keeps a torque step regular while the contacts are
  // still open at its first iterations.
  double driving_spring_N_m_per_rad = 0;
  std::vector<FeElementSet> stress_sets;  // stress output (e.g. a tooth's root fillets)
};

// Where a body's extra nodes and elements sit in the deck.
struct FeBodyLayout {
  int first_node = 0;  // deck id of mesh node 0
  int first_element = 0;  // deck id of quad 0
  int centre_node = 0;  // deck id of the centre node (translations)
  int rotation_node = 0;  // deck id of the rotation node (its dof 1 is the rotation, rad)
};

struct Deck {
  std::string text;  // the .inp
  std::vector<FeBodyLayout> layout;  // per body
  int steps = 0;  // 1 + load_fractions.size()
};

// Throws InputError (naming the body/contact) for an impossible definition.
Deck write_deck(const DeckDef& def);

}  // namespace gearsim::fe
