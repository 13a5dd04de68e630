// A cluster advanced as one rigid body in the Langevin bath (growth/rigid_cluster.hpp): built
// from its primaries' state and back; centre-of-mass diffusion D = kT / (n zeta) with the
// Ornstein-Uhlenbeck memory, the same as the engine's per-primary Langevin dynamics gives;
// rotational diffusion about the principal axes and the Maxwell distribution of the spin.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "engine/core/units.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/growth/brownian_conditions.hpp"
#include "engine/growth/ornstein_uhlenbeck.hpp"
#include "engine/growth/rigid_cluster.hpp"

using namespace aerobreak;

namespace {

// Mean square displacement per axis after t from rest (the Ornstein-Uhlenbeck position variance).
double variance_from_rest(double mass, double drag, double kt, double t) {
  const OrnsteinUhlenbeckStep s = ornstein_uhlenbeck_step(mass, drag, kt, t);
  return s.correlated_spread * s.correlated_spread + s.independent_spread * s.independent_spread;
}

RigidCluster dimer_at_rest(const PrimaryBath& bath) {
  const std::vector<Vec3> x{{-0.5, 0.0, 0.0}, {0.5, 0.0, 0.0}}, still(2);
  return rigid_cluster({0, 1}, x, still, still, bath);
}

}  // namespace

TEST_CASE("a rigid cluster keeps its primaries' positions and rigid motion") {
  const PrimaryBath bath{0.5, 1.0, 0.1, 0.2, 0.2 / 3.0, 1e-3};
  const std::vector<Vec3> x{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {1.0, 1.0, 1.0}};
  const Vec3 centre{0.75, 0.5, 0.25}, velocity{0.01, -0.02, 0.03}, omega{0.004, 0.005, -0.006};
  std::vector<Vec3> v, w;
  for (const Vec3& p : x) {
    v.push_back(velocity + cross(omega, p - centre));
    w.push_back(omega);
  }
  const RigidCluster c = rigid_cluster({4, 5, 6, 7}, x, v, w, bath);
  CHECK(c.mass == 4.0);
  CHECK(c.drag == Approx(0.8));
  CHECK(norm(c.centre - centre) < 1e-12);
  const std::vector<Vec3> placed = member_positions(c), moving = member_velocities(c);
  for (std::size_t k = 0; k < x.size(); ++k) {
    CHECK(norm(placed[k] - x[k]) < 1e-12);
    CHECK(norm(moving[k] - v[k]) < 1e-12);
  }
  CHECK(norm(angular_velocity(c) - omega) < 1e-12);
  // Trace of the inertia tensor: 2 m sum |r|^2 + 3 n (2/5) m R^2; of the drag, with zeta and zeta_r.
  double spread = 0.0;
  for (const Vec3& p : x) spread += norm2(p - centre);
  CHECK(c.inertia.x + c.inertia.y + c.inertia.z == Approx(2.0 * spread + 12.0 * 0.1));
  CHECK(c.rotational_drag.x + c.rotational_drag.y + c.rotational_drag.z ==
        Approx(0.2 * (2.0 * spread) + 12.0 * 0.2 / 3.0));
  CHECK(c.reach == Approx(std::sqrt(norm2(x[0] - centre)) + 0.5));
}

TEST_CASE("a lone rigid cluster diffuses as the engine's Langevin primaries do, D = kT / (n zeta)") {
  // Dimers of bonded primaries (sintered JKR contacts) at the growth's E_b / kT = 100 and a short
  // persistence length (0.05 d: memory m / zeta = 11 tau), from rest, over t = 10 m / zeta. The
  // centre of mass moves by the sum of the primaries' drag and noise whatever holds them together,
  // so its mean square displacement is 3 times the Ornstein-Uhlenbeck variance from rest of a body
  // of mass 2 m and drag 2 zeta, -> 6 D t with D = kT / (2 zeta). The engine (343 dimers, velocity
  // Verlet at its contact time step) and the rigid propagator (4000 dimers, ten steps) must both
  // give it within 4 standard errors, MSD sqrt(2 / (3 K)) for K clusters.
  const Material material = reduced_material(0.01, 0.3);
  ContactModelSpec model;
  model.rolling = model.twisting = true;
  model.critical_rolling = 0.1;
  const BrownianConditions b = brownian_conditions(material, model, 1.0, 1.0, 100.0, 0.05);
  const double t = 10.0 / b.drag;
  const double expected = 3.0 * variance_from_rest(2.0, 2.0 * b.drag, b.temperature, t);

  Particles p;
  const int side = 7;
  const double spacing = 5.0;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int k = 0; k < side; ++k) {
        const Vec3 centre{spacing * (i + 0.5), spacing * (j + 0.5), spacing * (k + 0.5)};
        p.add(centre - Vec3{0.466, 0.0, 0.0}, 0.5, material.density);
        p.add(centre + Vec3{0.466, 0.0, 0.0}, 0.5, material.density);
      }
  SimulationSettings settings;
  settings.periodic = PeriodicBox{{side * spacing, side * spacing, side * spacing}};
  settings.steps_per_period = 25.0;
  settings.initial_bond_gap = 0.01;
  settings.body.langevin = {b.temperature, b.drag_per_diameter, 3};
  Simulation sim(p, {material}, {}, model, settings);
  const std::vector<Vec3> start = sim.unwrapped_positions();
  sim.run(static_cast<std::int64_t>(std::round(t / sim.time_step())));
  const std::vector<Vec3> end = sim.unwrapped_positions();
  const int dimers = side * side * side;
  double engine = 0.0;
  for (int d = 0; d < dimers; ++d)
    engine += norm2(0.5 * (end[2 * d] + end[2 * d + 1] - start[2 * d] - start[2 * d + 1])) / dimers;

  const PrimaryBath bath{0.5, 1.0, 0.1, b.drag, b.drag / 3.0, b.temperature};
  RandomStream random(5);
  const int rigid_dimers = 4000;
  double rigid = 0.0;
  for (int d = 0; d < rigid_dimers; ++d) {
    RigidCluster c = dimer_at_rest(bath);
    const Vec3 from = c.centre;
    for (int s = 0; s < 10; ++s) propagate(c, t / 10.0, b.temperature, random);
    rigid += norm2(c.centre - from) / rigid_dimers;
  }
  INFO("MSD at t = " << t << " tau: engine " << engine << ", rigid " << rigid << ", Ornstein-Uhlenbeck " << expected
                     << " (6 D t = " << 6.0 * b.temperature / (2.0 * b.drag) * t << ")");
  CHECK(std::abs(engine - expected) < 4.0 * expected * std::sqrt(2.0 / (3.0 * dimers)));
  CHECK(std::abs(rigid - expected) < 4.0 * expected * std::sqrt(2.0 / (3.0 * rigid_dimers)));
  CHECK(sim.pair_events().broken == 0);
}

TEST_CASE("a rigid dimer's axis decorrelates by rotational diffusion, and its spin thermalises") {
  // Strong drag (rotational memory I / Z = 0.6 against t = 40): the axis u of a dimer keeps
  // <u(0).u(t)> = exp(-2 D_r t') with D_r = kT / Z_perp, Z_perp = zeta (1/2) + 2 zeta_r, where
  // 2 D_r t' is the angle variance per perpendicular axis from rest (Ornstein-Uhlenbeck, with
  // inertia I_perp = m / 2 + 2 (2/5) m R^2). The spin ends Maxwellian: <I_k Omega_k^2> = kT.
  // 4000 dimers: standard errors ~0.005 and ~kT sqrt(2 / 4000) = 0.022 kT.
  const PrimaryBath bath{0.5, 1.0, 0.1, 1.0, 1.0 / 3.0, 0.01};
  const double t = 40.0;
  const int dimers = 4000;
  const double angle_variance = variance_from_rest(0.5 + 0.2, 0.5 + 2.0 / 3.0, bath.temperature, t);
  RandomStream random(9);
  double correlation = 0.0, equipartition = 0.0;
  for (int d = 0; d < dimers; ++d) {
    RigidCluster c = dimer_at_rest(bath);
    const Vec3 axis = member_positions(c)[1] - member_positions(c)[0];
    for (int s = 0; s < 40; ++s) propagate(c, t / 40.0, bath.temperature, random);
    correlation += dot(member_positions(c)[1] - member_positions(c)[0], axis) / dimers;
    equipartition +=
        (c.inertia.x * c.spin.x * c.spin.x + c.inertia.y * c.spin.y * c.spin.y + c.inertia.z * c.spin.z * c.spin.z) /
        (3.0 * dimers);
  }
  INFO("<u(0).u(t)> " << correlation << " against " << std::exp(-angle_variance) << ", <I Omega^2> / kT "
                      << equipartition / bath.temperature);
  CHECK(std::abs(correlation - std::exp(-angle_variance)) < 0.02);
  CHECK(std::abs(equipartition / bath.temperature - 1.0) < 4.0 * std::sqrt(2.0 / (3.0 * dimers)));
}
