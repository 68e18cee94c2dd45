// TriMesh: an indexed triangle mesh in metres, the one mesh type every module exchanges
// (import, export, validation, mass properties, decomposition, rendering).
// Not a half-edge structure: topology queries live in mesh_validate.hpp.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace gearsim {

struct TriMesh {
  std::vector<Eigen::Vector3d> vertices;  // positions, m
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

}  // namespace gearsim
