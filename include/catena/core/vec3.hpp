#pragma once
// Small fixed-size linear algebra used across layers (Eigen's fixed-size types).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace catena {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
}  // namespace catena
