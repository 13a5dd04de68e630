#include "engine/growth/rigid_cluster.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "engine/growth/ornstein_uhlenbeck.hpp"

namespace aerobreak {
namespace {

Eigen::Vector3d eigen(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 vec3(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Eigen::Quaterniond quaternion(const RigidCluster& c) {
  return {c.orientation[0], c.orientation[1], c.orientation[2], c.orientation[3]};
}

double component_sum(const Vec3& v) { return v.x + v.y + v.z; }
Vec3 reciprocal(const Vec3& v) { return {1.0 / v.x, 1.0 / v.y, 1.0 / v.z}; }

// Largest dt with min(linear dt, quadratic dt^2) <= limit^2 (both bounds hold, so the larger of
// the two steps that meet one of them exactly is safe).
double step_within(double linear, double quadratic, double limit) {
  return std::max(limit * limit / linear, limit / std::sqrt(quadratic));
}

// One exact Ornstein-Uhlenbeck step per axis, two normals per axis in x, y, z order.
void advance_axes(const std::array<OrnsteinUhlenbeckStep, 3>& step, Vec3& x, Vec3& v, RandomStream& random) {
  double* position[3] = {&x.x, &x.y, &x.z};
  double* velocity[3] = {&v.x, &v.y, &v.z};
  for (int k = 0; k < 3; ++k) {
    const double g1 = random.standard_normal();
    step[k].advance(*position[k], *velocity[k], g1, random.standard_normal());
  }
}

}  // namespace

RigidCluster rigid_cluster(std::vector<std::size_t> members, std::span<const Vec3> position,
                           std::span<const Vec3> velocity, std::span<const Vec3> angular_velocity,
                           const PrimaryBath& bath) {
  RigidCluster c;
  c.members = std::move(members);
  const double n = static_cast<double>(c.members.size());
  for (std::size_t k = 0; k < position.size(); ++k) {
    c.centre += position[k];
    c.velocity += velocity[k];
  }
  c.centre = c.centre / n;
  c.velocity = c.velocity / n;

  // S = sum (|r|^2 1 - r r^T) and the angular momentum about the centre of mass.
  Eigen::Matrix3d shape = Eigen::Matrix3d::Zero();
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < position.size(); ++k) {
    const Eigen::Vector3d r = eigen(position[k] - c.centre);
    shape += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
    momentum += bath.mass * r.cross(eigen(velocity[k] - c.velocity)) + bath.inertia * eigen(angular_velocity[k]);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal(shape);
  Eigen::Matrix3d axes = principal.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);
  const Eigen::Quaterniond q(axes);
  c.orientation = {q.w(), q.x(), q.y(), q.z()};

  const Vec3 s = vec3(principal.eigenvalues());
  c.mass = n * bath.mass;
  c.drag = n * bath.drag;
  c.inertia = bath.mass * s + Vec3{1.0, 1.0, 1.0} * (n * bath.inertia);
  c.rotational_drag = bath.drag * s + Vec3{1.0, 1.0, 1.0} * (n * bath.spin_drag);
  const Vec3 spin_momentum = vec3(axes.transpose() * momentum);
  c.spin = {spin_momentum.x / c.inertia.x, spin_momentum.y / c.inertia.y, spin_momentum.z / c.inertia.z};
  for (std::size_t k = 0; k < position.size(); ++k) {
    c.body.push_back(vec3(axes.transpose() * eigen(position[k] - c.centre)));
    c.reach = std::max(c.reach, norm(c.body.back()) + bath.radius);
  }
  return c;
}

double propagate(RigidCluster& c, double dt, double temperature, RandomStream& random) {
  const Vec3 start = c.centre;
  const OrnsteinUhlenbeckStep translation = ornstein_uhlenbeck_step(c.mass, c.drag, temperature, dt);
  advance_axes({translation, translation, translation}, c.centre, c.velocity, random);
  // Rotation angles about the principal axes over the step, then one rotation by that vector in
  // the body frame (q <- q exp(phi / 2)).
  Vec3 angle;
  advance_axes({ornstein_uhlenbeck_step(c.inertia.x, c.rotational_drag.x, temperature, dt),
                ornstein_uhlenbeck_step(c.inertia.y, c.rotational_drag.y, temperature, dt),
                ornstein_uhlenbeck_step(c.inertia.z, c.rotational_drag.z, temperature, dt)},
               angle, c.spin, random);
  const double turn = norm(angle);
  if (turn > 0.0) {
    const Eigen::Quaterniond increment(Eigen::AngleAxisd(turn, eigen(angle / turn)));
    const Eigen::Quaterniond q = (quaternion(c) * increment).normalized();
    c.orientation = {q.w(), q.x(), q.y(), q.z()};
  }
  return norm(c.centre - start) + c.reach * turn;
}

Rotation orientation_matrix(const RigidCluster& c) {
  return Rotation::from_unit_quaternion(c.orientation[0], c.orientation[1], c.orientation[2], c.orientation[3]);
}

std::vector<Vec3> member_positions(const RigidCluster& c) {
  const Rotation r = orientation_matrix(c);
  std::vector<Vec3> x;
  x.reserve(c.body.size());
  for (const Vec3& b : c.body) x.push_back(c.centre + r.apply(b));
  return x;
}

std::vector<Vec3> member_velocities(const RigidCluster& c) {
  const Rotation r = orientation_matrix(c);
  const Vec3 omega = r.apply(c.spin);
  std::vector<Vec3> v;
  v.reserve(c.body.size());
  for (const Vec3& b : c.body) v.push_back(c.velocity + cross(omega, r.apply(b)));
  return v;
}

Vec3 angular_velocity(const RigidCluster& c) { return orientation_matrix(c).apply(c.spin); }

double step_for_reach(const RigidCluster& c, double temperature, double allowed, double max_angle) {
  const double lever = c.reach * c.reach;
  const double turn_linear = 2.0 * temperature * component_sum(reciprocal(c.rotational_drag));
  const double turn_quadratic = temperature * component_sum(reciprocal(c.inertia));
  const double reach_step = step_within(6.0 * temperature / c.drag + lever * turn_linear,
                                        3.0 * temperature / c.mass + lever * turn_quadratic, allowed);
  if (c.members.size() < 2) return reach_step;
  return std::min(reach_step, step_within(turn_linear, turn_quadratic, max_angle));
}

}  // namespace aerobreak
