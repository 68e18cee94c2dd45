// Bullet's working arrays for a btMultiBody's passes (articulated-body, Jacobians, forward
// kinematics and link velocities), kept between steps for their storage. Internal to physics/.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <vector>

namespace gearsim::physics {

struct BulletScratch {
  btAlignedObjectArray<btScalar> r;
  btAlignedObjectArray<btVector3> v;
  btAlignedObjectArray<btMatrix3x3> m;
  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  std::vector<btVector3> omega, vel;  // per link + 1 (the base first)
};

}  // namespace gearsim::physics
