#include "engine/dem/body_forces.hpp"

#include <cmath>
#include <numbers>

namespace aerobreak {
namespace {

// SplitMix64 finaliser (Steele, Lea & Flood 2014) as a counter-based generator.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double unit_interval(std::uint64_t bits) { return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53; }

// Six standard normal numbers for (seed, step, particle), by Box-Muller.
void gaussians(std::uint64_t seed, std::int64_t step, std::uint64_t particle, double out[6]) {
  std::uint64_t state = mix(seed ^ mix(static_cast<std::uint64_t>(step) ^ mix(particle)));
  for (int k = 0; k < 6; k += 2) {
    state = mix(state);
    const double u1 = unit_interval(state);
    state = mix(state);
    const double u2 = unit_interval(state);
    const double r = std::sqrt(-2.0 * std::log(u1));
    out[k] = r * std::cos(2.0 * std::numbers::pi * u2);
    out[k + 1] = r * std::sin(2.0 * std::numbers::pi * u2);
  }
}

}  // namespace

void add_body_forces(Particles& p, const BodyForces& body, std::int64_t step, double dt, std::size_t begin,
                     std::size_t end, double& work) {
  if (norm2(body.gravity) > 0.0)
    for (std::size_t i = begin; i < end; ++i) p.force[i] += p.mass[i] * body.gravity;
  if (!body.langevin.enabled()) return;

  const Langevin& l = body.langevin;
  // At zero temperature only the drag acts (relaxation): no noise to draw.
  const bool noisy = l.temperature > 0.0;
  for (std::size_t i = begin; i < end; ++i) {
    const double diameter = 2.0 * p.radius[i];
    const double zeta = l.drag_per_diameter * diameter;
    const double zeta_spin = zeta * diameter * diameter / 3.0;
    double g[6] = {};
    if (noisy) gaussians(l.seed, step, i, g);
    const double kick = std::sqrt(2.0 * zeta * l.temperature / dt);
    const double spin_kick = std::sqrt(2.0 * zeta_spin * l.temperature / dt);
    const Vec3 force = -zeta * p.velocity[i] + kick * Vec3{g[0], g[1], g[2]};
    const Vec3 torque = -zeta_spin * p.angular_velocity[i] + spin_kick * Vec3{g[3], g[4], g[5]};
    p.force[i] += force;
    p.torque[i] += torque;
    work += (dot(force, p.velocity[i]) + dot(torque, p.angular_velocity[i])) * dt;
  }
}

double gravitational_energy(const Particles& p, const Vec3& gravity) {
  double energy = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) energy -= p.mass[i] * dot(gravity, p.position[i]);
  return energy;
}

}  // namespace aerobreak
