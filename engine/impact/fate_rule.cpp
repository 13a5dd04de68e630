#include "engine/impact/fate_rule.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "engine/dem/simulation.hpp"
#include "engine/impact/fragment_paths.hpp"

namespace aerobreak {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

std::string name_of(std::size_t k, const Fragment& f) {
  return "fragment " + std::to_string(k + 1) + " (" + std::to_string(f.size) + " primar" + (f.size == 1 ? "y" : "ies") +
         ")";
}

// A symmetric 3x3 matrix (row-major: xx, xy, xz, yy, yz, zz).
struct Symmetric3 {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
};

Vec3 solve(const Symmetric3& a, const Vec3& b) {  // Cramer's rule
  const double det =
      a.xx * (a.yy * a.zz - a.yz * a.yz) - a.xy * (a.xy * a.zz - a.yz * a.xz) + a.xz * (a.xy * a.yz - a.yy * a.xz);
  const Vec3 c0{a.xx, a.xy, a.xz}, c1{a.xy, a.yy, a.yz}, c2{a.xz, a.yz, a.zz};
  const auto det3 = [](const Vec3& u, const Vec3& v, const Vec3& w) { return dot(u, cross(v, w)); };
  return {det3(b, c1, c2) / det, det3(c0, b, c2) / det, det3(c0, c1, b) / det};
}

double quadratic_form(const Symmetric3& a, const Vec3& e) {  // e.A.e
  return a.xx * e.x * e.x + a.yy * e.y * e.y + a.zz * e.z * e.z +
         2.0 * (a.xy * e.x * e.y + a.xz * e.x * e.z + a.yz * e.y * e.z);
}

// The smallest and largest eigenvalues of a symmetric 3x3 matrix (the trigonometric solution of
// its characteristic cubic).
std::pair<double, double> eigenvalue_range(const Symmetric3& a) {
  const double q = (a.xx + a.yy + a.zz) / 3.0;
  const double p1 = a.xy * a.xy + a.xz * a.xz + a.yz * a.yz;
  const double p2 = (a.xx - q) * (a.xx - q) + (a.yy - q) * (a.yy - q) + (a.zz - q) * (a.zz - q) + 2.0 * p1;
  const double p = std::sqrt(p2 / 6.0);
  if (!(p > 0.0)) return {q, q};
  const Symmetric3 b{(a.xx - q) / p, a.xy / p, a.xz / p, (a.yy - q) / p, a.yz / p, (a.zz - q) / p};
  const double det_b =
      b.xx * (b.yy * b.zz - b.yz * b.yz) - b.xy * (b.xy * b.zz - b.yz * b.xz) + b.xz * (b.xy * b.yz - b.yy * b.xz);
  const double phi = std::acos(std::clamp(det_b / 2.0, -1.0, 1.0)) / 3.0;
  return {q + 2.0 * p * std::cos(phi + 2.0 * std::numbers::pi / 3.0), q + 2.0 * p * std::cos(phi)};
}

// What the rule reads of one fragment besides Fragment: its energies, the rigid rotation its
// angular momentum gives it, and its lightest primary.
struct Reserve {
  double kinetic = 0.0;      // in the wall's frame, translation and spin of its primaries
  double own_kinetic = 0.0;  // in its own frame (about its centre of mass)
  double above_rest = 0.0;   // stored in its contacts (bonds and wall contacts) above their rest
  double weakest_bond = kInfinity;
  double weakest_pull = kInfinity;  // the least pull-off force of its bonds
  double weakest_wall_contact = kInfinity;
  double lightest = kInfinity;
  double stretch = 0.0;       // the most one of its bonds can still stretch: its overlap + delta_b
  double landing_loop = 0.0;  // a primary alone: its adhesion loop with the wall
  Vec3 momentum;              // angular momentum about the centre of mass
  Symmetric3 inertia;         // inertia tensor about the centre of mass
  Symmetric3 orbital;         // its part from the primaries' positions (without their own moments)
  double own_moments = 0.0;   // the rest: the sum of the primaries' own moments
  // The rigid rotation with that angular momentum, w = I^-1 L: its kinetic energy, the fastest
  // spin it can reach as the fragment tumbles, (2 E / I_min)^(1/2), the most it can pull on a bond
  // (rotation_pull), and the kinetic energy of the primaries' motion relative to it (their own
  // spins left out: without twisting resistance a primary spins about its bond for ever and loads
  // no contact).
  Vec3 spin;
  double rotation = 0.0;
  double fastest_spin = 0.0;
  double pull = 0.0;
  double deformation = 0.0;
  double unwinding = 0.0;  // what the rotation can give up while a bond opens (rotation_unwinding)
};

void add_particle(Reserve& f, const Fragment& fragment, const Particles& p, std::size_t i) {
  const Vec3 r = p.position[i] - fragment.centre_of_mass;
  const Vec3 u = p.velocity[i] - fragment.velocity;
  f.kinetic += 0.5 * p.mass[i] * norm2(p.velocity[i]) + 0.5 * p.inertia[i] * norm2(p.angular_velocity[i]);
  f.own_kinetic += 0.5 * p.mass[i] * norm2(u) + 0.5 * p.inertia[i] * norm2(p.angular_velocity[i]);
  f.lightest = std::min(f.lightest, p.mass[i]);
  f.momentum += p.mass[i] * cross(r, u) + p.inertia[i] * p.angular_velocity[i];
  const double m = p.mass[i], r2 = norm2(r), own = p.inertia[i];
  Symmetric3& t = f.orbital;
  t.xx += m * (r2 - r.x * r.x);
  t.yy += m * (r2 - r.y * r.y);
  t.zz += m * (r2 - r.z * r.z);
  t.xy -= m * r.x * r.y;
  t.xz -= m * r.x * r.z;
  t.yz -= m * r.y * r.z;
  f.own_moments += own;
}

// What a fragment's rigid rotation (energy E, about the axis e of its spin) can give up while a bond
// stretches by s (f.stretch) before it lets go; M its mass. Stretching moves each primary at most s
// further from the centre of mass, so the orbital moment about e, x = e.I_orb.e, grows to at most (x^(1/2) + s
// M^(1/2))^2 (Minkowski), while the primaries' own moments c stay; at fixed angular momentum the rotation's energy
// falls in proportion to the moment, so at most E (1 - (x + c) / ((x^(1/2) + s M^(1/2))^2 + c)) goes into the stretch:
// the energy a spinning dimer's bond draws from its orbit as it opens. (The rule keeps a fragment's shape otherwise: a
// tumbling fragment's drift to its largest axis is not counted.)
double rotation_unwinding(const Reserve& f, double mass) {
  const double rate = norm(f.spin);
  if (!(f.rotation > 0.0 && rate > 0.0)) return 0.0;
  const double x = std::max(quadratic_form(f.orbital, f.spin / rate), 0.0);
  const double reach = std::sqrt(x) + f.stretch * std::sqrt(mass);
  return f.rotation * (1.0 - (x + f.own_moments) / (reach * reach + f.own_moments));
}

// The most a rigid rotation of kinetic energy E pulls on any bond. A bond carries the centripetal
// force of the primaries on one side of it, which equals that of the other side (their sum
// vanishes about the centre of mass): at most half the sum over all primaries,
// sum m_i |w x (w x r_i)| <= |w| (M sum m_i |w x r_i|^2)^(1/2) = |w| (M w.I_orb.w)^(1/2), with
// |w|^2 = 2 E / (e.I.e), e the axis, I = I_orb + c the inertia (c the primaries' own moments): so at
// most E (M x / (x + c)^2)^(1/2), x = e.I_orb.e within I_orb's eigenvalues [low, high], largest at
// x = c. (A dimer turning end over end pulls with 1.43 E; the bound gives 1.58 E.)
double rotation_pull(double energy, double mass, double low, double high, double own) {
  const double x = std::clamp(own, low, high);
  return energy * std::sqrt(mass * x / ((x + own) * (x + own)));
}

std::vector<Reserve> reserves_of(const Simulation& sim, const FragmentAnalysis& fa) {
  const Particles& p = sim.particles();
  std::vector<Reserve> r(fa.fragments.size());
  for (std::size_t i = 0; i < p.size(); ++i) add_particle(r[fa.fragment_of[i]], fa.fragments[fa.fragment_of[i]], p, i);
  for (std::size_t k = 0; k < r.size(); ++k) {
    Reserve& f = r[k];
    f.inertia = f.orbital;
    f.inertia.xx += f.own_moments;
    f.inertia.yy += f.own_moments;
    f.inertia.zz += f.own_moments;
    f.spin = solve(f.inertia, f.momentum);
    f.rotation = std::min(0.5 * dot(f.spin, f.momentum), f.own_kinetic);
    const auto [low, high] = eigenvalue_range(f.orbital);
    f.fastest_spin = std::sqrt(2.0 * f.rotation / (low + f.own_moments));
    f.pull = rotation_pull(f.rotation, fa.fragments[k].mass, low, high, f.own_moments);
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Fragment& fragment = fa.fragments[fa.fragment_of[i]];
    Reserve& f = r[fa.fragment_of[i]];
    const Vec3 rigid = fragment.velocity + cross(f.spin, p.position[i] - fragment.centre_of_mass);
    f.deformation += 0.5 * p.mass[i] * norm2(p.velocity[i] - rigid);
  }
  sim.contacts().for_each([&](const ContactState& c) {
    if (c.with_wall && c.j != 0) return;
    Reserve& f = r[fa.fragment_of[c.i]];
    const Simulation::ContactReserve reserve = sim.contact_reserve(c);
    f.above_rest += reserve.above_rest;
    double& weakest = c.with_wall ? f.weakest_wall_contact : f.weakest_bond;
    weakest = std::min(weakest, reserve.to_break);
    if (c.with_wall) return;
    f.weakest_pull = std::min(f.weakest_pull, c.constants.pull_off_force);
    f.stretch = std::max(f.stretch, c.overlap + c.constants.break_overlap);
  });
  for (std::size_t k = 0; k < r.size(); ++k) r[k].unwinding = rotation_unwinding(r[k], fa.fragments[k].mass);
  if (!sim.walls().empty() && sim.walls().front().adhesive)
    for (std::size_t k = 0; k < fa.fragments.size(); ++k)
      if (fa.fragments[k].size == 1) r[k].landing_loop = sim.wall_loop_energy(fa.fragments[k].first_primary, 0);
  return r;
}

// Off the wall and moving away: can its lowest point still come back? Each primary moves relative
// to the centre of mass at most at u = w R_b + (2 E / m_lightest)^(1/2), w the fastest spin of its
// rotation, R_b its bounding radius and E its internal energy; and, with too little internal energy
// to break a bond (checked before), it keeps its shape: its primaries stay within its bounding
// sphere, taken a tenth of a diameter wider. So the lowest gap is at least
// max(g0 + (v_n - u) t, z_cm - 1.1 R_b + v_n t), whose least value over t >= 0 must stay above 0
// (the two bounds cross at t = (g0 - z_cm + 1.1 R_b) / u). A primary alone keeps its lowest point
// at its centre less its radius.
bool cannot_return(const Fragment& f, const Reserve& r, double internal, double height) {
  if (f.size == 1) return true;
  if (!(f.lowest_gap > 0.0)) return false;
  const double drift = r.fastest_spin * f.bounding_radius + std::sqrt(2.0 * std::max(internal, 0.0) / r.lightest);
  const double v = f.normal_velocity;
  if (v >= drift) return true;
  const double reach = height - 1.1 * f.bounding_radius;
  return reach + v * std::max((f.lowest_gap - reach) / drift, 0.0) > 0.0;
}

// A fragment of several primaries off a wall without adhesion that cannot break: its energy in the
// wall's frame, kinetic and stored above rest, is below its weakest bond's E_b. The wall does no work
// on it but loses some (damping, friction), so that energy never rises, and a bond lets go only once
// its own stored energy has risen by E_b: it stays whole whatever it meets at the wall, and it
// cannot stay there. Its path: until it can first touch the wall its centre moves on its straight
// line, and that is no sooner than its lowest gap closed at v_n's approach plus the fastest a
// primary moves about the centre of mass, (2 E_own / m_lightest)^(1/2), E_own its energy in its own
// frame; from then on its centre stays within a ball about where it was then that grows at the most
// its centre's speed can be, (2 E / M)^(1/2), its bounding sphere taken a tenth wider (it may flex
// within its bonds' reach). False if it is not such a fragment.
bool rebounding_path(const Fragment& f, const Reserve& r, const Wall& wall, FragmentPath& path) {
  const double energy = r.kinetic + r.above_rest;
  if (wall.adhesive || f.size == 1 || !(energy < r.weakest_bond)) return false;
  const double about_centre = std::sqrt(2.0 * (r.own_kinetic + r.above_rest) / r.lightest);
  const double closing = about_centre - f.normal_velocity;
  path.radius = 1.1 * f.bounding_radius;
  path.stop = closing > 0.0 ? std::max(f.lowest_gap, 0.0) / closing : kInfinity;
  path.after = Vec3{};
  path.spread = std::sqrt(2.0 * energy / f.mass);
  return true;
}

// Sorts one fragment into its fate; returns its path, or why its fate is open.
struct Verdict {
  std::string open;
  FragmentPath path;
  bool held = false;
};

Verdict fate_of(std::size_t k, Fragment& f, const Reserve& r, const Wall& wall, double friction,
                const Vec3& mean_along_wall) {
  const std::string name = name_of(k, f);
  const Vec3 n = wall.normal / norm(wall.normal);
  const double height = dot(f.centre_of_mass - wall.point, n);
  // On the wall a primary alone can leave only by its motion along the normal (the wall's forces
  // along it do not lift it); a larger fragment can turn motion along the wall into motion off it.
  const double wall_energy =
      (f.size == 1 ? 0.5 * f.mass * f.normal_velocity * f.normal_velocity : r.kinetic) + r.above_rest;
  // In flight, what can pull a bond apart: the motion relative to the rigid rotation, whose angular
  // momentum the fragment keeps, the energy its contacts store above rest, and what the rotation
  // gives up as a bond opens (rotation_unwinding); and the rotation itself, by its centripetal pull
  // (rotation_pull).
  const double internal = r.deformation + r.above_rest + r.unwinding;
  Verdict v;
  v.path = {f.centre_of_mass, f.velocity, f.bounding_radius, kInfinity, Vec3{}, 0.0};
  if (f.on_wall()) {
    if (!wall.adhesive) return {name + " touches a wall without adhesion", v.path};
    const double hold = std::min(r.weakest_wall_contact, f.size > 1 ? r.weakest_bond : kInfinity);
    if (!(wall_energy < hold))
      return {name + " on the wall has energy " + number(wall_energy) + ", not below the " + number(hold) +
                  " that frees its weakest contact",
              v.path};
    // It may still creep along the wall: on the course of its mean velocity along it.
    v.path.velocity = mean_along_wall;
    v.held = true;
    return v;
  }
  const double speed = f.normal_velocity;
  if (speed > 0.0) {
    std::string open;
    if (f.size > 1 && !(internal < r.weakest_bond))
      open = name + " has internal energy " + number(internal) + ", not below its weakest bond's " +
             number(r.weakest_bond);
    else if (f.size > 1 && !(r.pull < r.weakest_pull))
      open = name + " spins fast enough to pull a bond apart (" + number(r.pull) + " against " +
             number(r.weakest_pull) + ")";
    else if (!cannot_return(f, r, internal, height))
      open = name + " moves away from the wall but may still swing back to it";
    if (!open.empty() && rebounding_path(f, r, wall, v.path))
      f.bouncing = true;
    else
      v.open = open;
    return v;
  }
  if (!(speed < 0.0)) return {name + " moves along the wall", v.path};
  if (rebounding_path(f, r, wall, v.path)) {
    f.bouncing = true;
    return v;
  }
  v.path.stop = f.lowest_gap / -speed;
  const Vec3 tangential = f.velocity - speed * n;
  if (wall.adhesive) {
    // A primary alone meets a flat wall head-on in the normal direction whatever it does along it:
    // friction and rolling resistance act along the wall, so only 1/2 m v_n^2 meets the adhesion loop.
    if (f.size > 1 || !(0.5 * f.mass * speed * speed < r.landing_loop))
      return {name + " is on its way back to the wall (normal speed " + number(speed) + ")", v.path};
    v.path.after = tangential;
    f.landing = true;
    return v;
  }
  if (f.size > 1) return {name + " is on its way back to the wall (normal speed " + number(speed) + ")", v.path};
  // A primary alone bounces off (a wall without adhesion cannot hold it, and without gravity
  // nothing brings it back) with a normal speed between 0 and its speed now, and its tangential
  // velocity changed by at most the Coulomb limit on the normal impulse, 2 mu |v_n|: its centre
  // then moves at after = v_t + |v_n| / 2 n within a ball growing at
  // ((2 mu |v_n|)^2 + (|v_n| / 2)^2)^(1/2).
  v.path.after = tangential - 0.5 * speed * n;
  v.path.spread = std::hypot(2.0 * friction * speed, 0.5 * speed);
  f.bouncing = true;
  return v;
}

// Each fragment's mean velocity along the wall since `earlier` (that of its centre of mass if the
// time is the same).
std::vector<Vec3> mean_along_wall(const Simulation& sim, const FragmentAnalysis& fa,
                                  const std::vector<Vec3>& earlier_positions, double earlier) {
  const Particles& p = sim.particles();
  const Vec3 n = sim.walls().front().normal / norm(sim.walls().front().normal);
  const double elapsed = sim.time() - earlier;
  std::vector<Vec3> mean(fa.fragments.size());
  if (elapsed > 0.0 && earlier_positions.size() == p.size()) {
    for (std::size_t i = 0; i < p.size(); ++i)
      mean[fa.fragment_of[i]] += p.mass[i] * (p.position[i] - earlier_positions[i]);
    for (std::size_t k = 0; k < mean.size(); ++k) mean[k] = mean[k] / (fa.fragments[k].mass * elapsed);
  } else {
    for (std::size_t k = 0; k < mean.size(); ++k) mean[k] = fa.fragments[k].velocity;
  }
  for (Vec3& v : mean) v = v - dot(v, n) * n;
  return mean;
}

// The lowest gap to the wall fragment k reaches from now on if it turns rigidly at `spin` about
// a fixed axis through its centre of mass while the centre rises at its normal velocity v_n > 0,
// until its bounding sphere (taken 0.1 d wider, as in cannot_return) has cleared the wall. A
// primary at r from the centre is then at height h + v_n t + a + b cos wt + c sin wt, with a, b, c
// the wall-normal parts of r along the axis, across it and of axis x r. Sampled every kTurnStep
// radians of the turn; each sample is lowered by how far any primary can fall in half the time
// between samples, (|w| R_b + v_n) dt / 2, so that the least value is a lower bound for the rigid
// motion. Infinite if nothing can come near the wall; -infinity if the horizon takes more than
// kMostSamples samples.
double lowest_rigid_gap(const Particles& p, const FragmentAnalysis& fa, std::size_t k, const Vec3& spin,
                        const Wall& wall, double height) {
  constexpr double kTurnStep = 0.002;
  constexpr double kMostSamples = 20000;
  const Fragment& f = fa.fragments[k];
  const Vec3 n = wall.normal / norm(wall.normal);
  const double v = f.normal_velocity;
  const double rate = norm(spin);
  const double horizon = std::max(0.0, (1.1 * f.bounding_radius - height) / v);
  if (!(horizon > 0.0)) return kInfinity;
  const double samples = std::ceil(rate * horizon / kTurnStep) + 1.0;
  if (samples > kMostSamples) return -kInfinity;
  const Vec3 axis = rate > 0.0 ? spin / rate : n;
  struct Arm {
    double along, cosine, sine;  // a - radius, b, c
  };
  std::vector<Arm> arms;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (fa.fragment_of[i] != k) continue;
    const Vec3 r = p.position[i] - f.centre_of_mass;
    const Vec3 along = dot(r, axis) * axis;
    arms.push_back({dot(along, n) - p.radius[i], dot(r - along, n), dot(cross(axis, r), n)});
  }
  const double dt = horizon / samples;
  const double fall = 0.5 * dt * (rate * f.bounding_radius + v);
  double lowest = kInfinity;
  for (double s = 0.0; s <= samples; s += 1.0) {
    const double t = s * dt, c = std::cos(rate * t), sn = std::sin(rate * t);
    for (const Arm& a : arms) lowest = std::min(lowest, height + v * t + a.along + a.cosine * c + a.sine * sn - fall);
  }
  return lowest;
}

}  // namespace

FatesJudgement judge_fates(const Simulation& sim, const std::vector<Vec3>& earlier_positions, double earlier) {
  FatesJudgement j;
  j.fragments = find_fragments(sim);
  std::vector<Fragment>& fragments = j.fragments.fragments;
  for (const Fragment& f : fragments) j.velocities.push_back(f.velocity);
  // Fragments apart move on straight lines only without forces at a distance.
  if (sim.walls().empty() || sim.model().van_der_waals || norm2(sim.body_forces().gravity) > 0.0 ||
      sim.body_forces().langevin.enabled()) {
    j.reason = "fragments apart feel forces (van der Waals, gravity, Langevin) or there is no wall";
    return j;
  }
  const Wall& wall = sim.walls().front();
  const std::vector<Reserve> reserves = reserves_of(sim, j.fragments);
  const std::vector<Vec3> along_wall = mean_along_wall(sim, j.fragments, earlier_positions, earlier);
  const double friction = sim.model().tangential ? sim.model().friction : 0.0;
  std::vector<Verdict> verdicts;
  for (std::size_t k = 0; k < fragments.size(); ++k) {
    verdicts.push_back(fate_of(k, fragments[k], reserves[k], wall, friction, along_wall[k]));
    if (verdicts.back().held) j.velocities[k] = along_wall[k];
    if (!verdicts.back().open.empty()) {
      j.reason = verdicts.back().open;
      return j;
    }
  }
  if (fragments.front().landing || fragments.front().bouncing) {
    j.reason = name_of(0, fragments.front()) + ", the largest, is on its way back to the wall";
    return j;
  }
  for (std::size_t a = 0; a < fragments.size(); ++a)
    for (std::size_t b = a + 1; b < fragments.size(); ++b) {
      // Two held fragments that do not approach each other cannot meet (a held fragment's course
      // along the wall is known only roughly: its bounding sphere may overlap another's from the
      // start); one moving towards another is tested on its course. Every other pair, two bouncing
      // primaries too, is tested on its paths: each path holds every course its fragment can take.
      const Vec3 apart = fragments[b].centre_of_mass - fragments[a].centre_of_mass;
      const Vec3 closing = verdicts[b].path.velocity - verdicts[a].path.velocity;
      if (verdicts[a].held && verdicts[b].held && dot(apart, closing) >= 0.0) continue;
      if (paths_can_meet(verdicts[a].path, verdicts[b].path)) {
        j.reason = name_of(a, fragments[a]) + " and " + name_of(b, fragments[b]) + " can still meet";
        return j;
      }
    }
  return j;
}

std::string swing_back_reason(const Simulation& sim, bool follow_rigid_turn) {
  if (sim.walls().empty()) return {};
  const FragmentAnalysis fa = find_fragments(sim);
  const std::vector<Reserve> reserves = reserves_of(sim, fa);
  const Wall& wall = sim.walls().front();
  const Vec3 n = wall.normal / norm(wall.normal);
  for (std::size_t k = 0; k < fa.fragments.size(); ++k) {
    const Fragment& f = fa.fragments[k];
    if (f.on_wall() || !(f.normal_velocity > 0.0)) continue;
    const double height = dot(f.centre_of_mass - wall.point, n);
    if (cannot_return(f, reserves[k], 0.0, height)) continue;
    if (!follow_rigid_turn) return name_of(k, f) + " turns fast enough to swing back to the wall";
    if (!(lowest_rigid_gap(sim.particles(), fa, k, reserves[k].spin, wall, height) > 0.0))
      return name_of(k, f) + " turns so that it may swing back to the wall";
  }
  return {};
}

}  // namespace aerobreak
