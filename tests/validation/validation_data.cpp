// Data behind the validation figures of docs/VALIDATION.md (drawn by docs/validation/make_figures.sh).
// Usage: validation_data OUTPUT_DIRECTORY. Writes, in reduced units (d = 1, m = 1, k_n = 1,
// tau = sqrt(m/k_n)):
//   restitution.csv      unit sphere on an adhesive wall (JKR): e(v) against the JKR hysteresis loss
//   jkr_force.csv        F/F_c versus delta/delta_c of the JKR law (report eqs 2, 5, figure 1) and Hertz
//   energy.csv           energy budget of a relaxed BCCA cluster hitting a wall, full contact model
//   conservation.csv     energy error of an oscillating JKR dimer versus steps per contact period
//   rg_vs_n.csv          BCCA radius of gyration versus N (report figure 2b), rg_samples.csv, rg_fit.csv
//   summary.txt          the numbers quoted in docs/VALIDATION.md
// Not a test: it asserts nothing. It is deterministic (fixed seeds) and runs in a few seconds.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/fractal_scaling_fit.hpp"
#include "engine/contact/contact_constants.hpp"
#include "engine/contact/normal_hertz.hpp"
#include "engine/contact/normal_jkr.hpp"
#include "engine/core/material.hpp"
#include "engine/core/units.hpp"
#include "engine/dem/impact_placement.hpp"
#include "engine/dem/relaxation.hpp"
#include "engine/dem/simulation.hpp"
#include "tests/engine/support.hpp"

using namespace aerobreak;

namespace {

constexpr double kGammaOverKn = 0.01;
constexpr double kPoisson = 0.3;
const double pi = std::numbers::pi;
const double unit_density = 6.0 / pi;  // m = 1 for d = 1

Material unit_material() { return reduced_material(kGammaOverKn, kPoisson); }

// Contact constants of a unit sphere against a wall (R* = R = 1/2, m* = m = 1) or of two unit
// spheres (R* = 1/4, m* = 1/2), completed by the JKR law: a0, F_c, delta_c.
ContactConstants jkr_constants(bool wall) {
  const PairMaterial pm = combine(unit_material(), unit_material());
  ContactConstants c = wall ? sphere_wall_constants(0.5, 1.0, pm) : sphere_pair_constants(0.5, 1.0, 0.5, 1.0, pm);
  JkrNormal{}.complete(c);
  return c;
}

// Energy lost in one JKR contact cycle (made at delta = 0, broken at delta = -delta_c, or at
// F = -F_c by the force rule): the work of eq 1, F(a) = 4E*a^3/(3R*) - sqrt(8 pi w E* a^3), along
// eq 2, delta(a) = a^2/R* - sqrt(2 pi w a/E*), from the release radius (d delta/da = 0, or
// dF/da = 0) to the touching radius (delta = 0). Integrated by 2000-panel Gauss-Legendre
// (3 points) in s = sqrt(a), where F d(delta)/ds is a polynomial (so the quadrature is exact up to
// round-off). Written independently of tests/engine/jkr_restitution_test.cpp.
double hysteresis_loss(const ContactConstants& c, JkrSeparation rule) {
  const double e = c.modulus, w = c.work_of_adhesion, r = c.radius;
  const auto integrand = [&](double s) {
    const double a = s * s;
    const double force = 4.0 * e * a * a * a / (3.0 * r) - std::sqrt(8.0 * pi * w * e * a * a * a);
    const double ddelta_da = 2.0 * a / r - 0.5 * std::sqrt(2.0 * pi * w / (e * a));
    return -force * ddelta_da * 2.0 * s;  // work done against the (attractive) force, da = 2 s ds
  };
  const double a_break = std::cbrt((rule == JkrSeparation::displacement ? 1.0 : 9.0) * pi * w * r * r / (8.0 * e));
  const double a_touch = std::cbrt(2.0 * pi * w * r * r / e);
  const double lo = std::sqrt(a_break), hi = std::sqrt(a_touch);
  const int panels = 2000;
  const double h = (hi - lo) / panels;
  const double node = std::sqrt(0.6);
  double sum = 0.0;
  for (int k = 0; k < panels; ++k) {
    const double mid = lo + (k + 0.5) * h;
    const double left = integrand(mid - 0.5 * h * node), right = integrand(mid + 0.5 * h * node);
    sum += (5.0 * left + 8.0 * integrand(mid) + 5.0 * right) / 18.0;
  }
  return sum * h;
}

std::ofstream open(const std::filesystem::path& dir, const char* name) {
  std::ofstream out(dir / name);
  if (!out) throw std::runtime_error(std::string("cannot write ") + (dir / name).string());
  out.precision(10);
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---------------------------------------------------------------------------------------------
// 1. Coefficient of restitution of a sphere hitting an adhesive wall head-on, at the automatic
// time step (docs/MODEL.md 9.2), by both separation rules.

struct Bounce {
  double restitution = 0.0;  // 0 when the sphere stuck
  double time_step = 0.0;
  double deepest = 0.0;  // largest overlap with the wall, in d
};

Bounce throw_sphere(double speed, JkrSeparation rule, double dissipative_time) {
  ContactModelSpec spec;
  spec.normal = NormalLaw::jkr;
  spec.separation = rule;
  spec.tangential = false;
  if (dissipative_time > 0.0) {
    spec.damping = DampingLaw::viscoelastic;
    spec.dissipative_time = dissipative_time;
  }
  const double gap = 1e-3;
  Particles p;
  p.add({0.0, 0.0, 0.5 + gap}, 0.5, unit_density);
  p.velocity[0] = {0.0, 0.0, -speed};
  Simulation sim(std::move(p), {unit_material()}, {Wall{}}, spec);
  const double limit = 100.0 * sim.time_step_estimate().period + gap / speed;
  bool touched = false;
  double deepest = 0.0;
  while (sim.time() < limit) {
    sim.step();
    deepest = std::max(deepest, 0.5 - sim.particles().position[0].z);
    const bool in_contact = sim.contacts().size() > 0;
    touched = touched || in_contact;
    if (touched && !in_contact) {
      sim.step();  // the second half kick of the last step's force
      return {sim.particles().velocity[0].z / speed, sim.time_step(), deepest};
    }
  }
  return {0.0, sim.time_step(), deepest};  // still in contact after 100 contact periods: stuck
}

// What one rule's series shows, for the summary.
struct RestitutionSeries {
  double worst = 0.0, worst_at = 0.0;  // largest |e_sim / e_theory - 1| and its v / v_c
  double stick_below = 0.0, bounce_above = 1e300;
  double overlap_at_vc = 0.0, overlap_at_top = 0.0;  // deepest overlap at v = v_c and at 20 v_c, d
};

RestitutionSeries restitution_series(std::ofstream& out, JkrSeparation rule, double loss, const ContactConstants& c) {
  const double critical_speed = std::sqrt(2.0 * loss / c.mass);
  const int count = 40;
  RestitutionSeries series;
  for (int k = 0; k < count; ++k) {
    const double ratio = 0.5 * std::pow(40.0, static_cast<double>(k) / (count - 1));  // 0.5 .. 20
    const double v = ratio * critical_speed;
    const double impact_energy = 0.5 * c.mass * v * v;
    const double theory = impact_energy > loss ? std::sqrt(1.0 - loss / impact_energy) : 0.0;
    const Bounce elastic = throw_sphere(v, rule, 0.0);
    const double damped = rule == JkrSeparation::displacement ? throw_sphere(v, rule, 0.05).restitution : NAN;
    out << (rule == JkrSeparation::displacement ? 0 : 1) << ',' << ratio << ',' << elastic.restitution << ',' << theory
        << ',' << damped << ',' << v << ',' << elastic.deepest << ',' << elastic.time_step << '\n';
    if (ratio <= 1.0) series.overlap_at_vc = elastic.deepest;
    series.overlap_at_top = elastic.deepest;
    if (elastic.restitution == 0.0)
      series.stick_below = std::max(series.stick_below, ratio);
    else
      series.bounce_above = std::min(series.bounce_above, ratio);
    if (theory > 0.0 && elastic.restitution > 0.0 && std::fabs(elastic.restitution / theory - 1.0) > series.worst) {
      series.worst = std::fabs(elastic.restitution / theory - 1.0);
      series.worst_at = ratio;
    }
  }
  return series;
}

void restitution(const std::filesystem::path& dir, std::FILE* summary) {
  const ContactConstants c = jkr_constants(true);
  std::ofstream out = open(dir, "restitution.csv");
  out << "rule,v_over_vc,e_simulated,e_theory,e_damped,v,max_overlap,time_step\n";
  for (auto rule : {JkrSeparation::displacement, JkrSeparation::force}) {
    const char* name = rule == JkrSeparation::displacement ? "displacement" : "force";
    const double loss = hysteresis_loss(c, rule);
    std::fprintf(summary, "restitution (%s rule): U_b = %.6e = %.6f F_c delta_c, v_c = %.6e d/tau\n", name, loss,
                 loss / (c.pull_off_force * c.critical_overlap), std::sqrt(2.0 * loss / c.mass));
    const RestitutionSeries s = restitution_series(out, rule, loss, c);
    std::fprintf(summary, "restitution (%s rule): sticks up to v/v_c = %.4f, bounces from %.4f\n", name, s.stick_below,
                 s.bounce_above);
    std::fprintf(summary, "restitution (%s rule): max |e_sim / e_theory - 1| = %.3e at v/v_c = %.3f\n", name, s.worst,
                 s.worst_at);
    std::fprintf(summary, "restitution (%s rule): deepest overlap %.4f d at v/v_c = 1, %.4f d at v/v_c = 20\n", name,
                 s.overlap_at_vc, s.overlap_at_top);
  }
  double damped_stick_below = 0.0;
  for (double ratio = 1.0; ratio < 2.0; ratio += 0.01) {
    const double v = ratio * std::sqrt(2.0 * hysteresis_loss(c, JkrSeparation::displacement) / c.mass);
    if (throw_sphere(v, JkrSeparation::displacement, 0.05).restitution > 0.0) break;
    damped_stick_below = ratio;
  }
  std::fprintf(summary, "restitution: damped (A = 0.05) sticks up to v/v_c = %.2f\n", damped_stick_below);
}

// ---------------------------------------------------------------------------------------------
// 2. The JKR force-overlap curve (report figure 1) and the Hertz curve.

void jkr_force(const std::filesystem::path& dir, std::FILE* summary) {
  const ContactConstants c = jkr_constants(false);
  ContactConstants hertz_c = c;
  HertzNormal{}.complete(hertz_c);
  const JkrNormal jkr;
  const double fc = c.pull_off_force, dc = c.critical_overlap, a0 = c.equilibrium_radius;
  std::ofstream out = open(dir, "jkr_force.csv");
  // branch: 0 loading (approach), 1 unloading (retraction); law = JkrNormal::respond (0 when not in
  // contact); theory = eq 5 at the a of eq 2 (NaN off the branch); hertz = HertzNormal::respond.
  out << "branch,delta_over_deltac,F_law_over_Fc,F_theory_over_Fc,F_hertz_over_Fc\n";
  const double top = 6.0;
  const int n = 400;
  double worst = 0.0;
  const auto theory_at = [&](double delta) {
    // Eq 2 inverted by bisection on the stable branch a/a0 >= (1/6)^(2/3): independent of the
    // law's closed form.
    double lo = std::pow(1.0 / 6.0, 2.0 / 3.0), hi = 10.0;
    const auto d_of = [&](double x) { return std::cbrt(6.0) * (2.0 * x * x - 4.0 / 3.0 * std::sqrt(x)); };
    for (int k = 0; k < 200; ++k) {
      const double mid = 0.5 * (lo + hi);
      (d_of(mid) < delta / dc ? lo : hi) = mid;
    }
    const double x = 0.5 * (lo + hi);
    return 4.0 * (x * x * x - std::pow(x, 1.5));  // eq 5
  };
  const auto row = [&](int branch, double ratio, bool in_contact) {
    const double delta = ratio * dc;
    const double law = in_contact ? jkr.respond(delta, c).force / fc : 0.0;
    const double hertz = delta > 0.0 ? HertzNormal{}.respond(delta, hertz_c).force / fc : NAN;
    const double theory = in_contact ? theory_at(delta) : NAN;
    if (in_contact) worst = std::max(worst, std::fabs(law - theory));
    out << branch << ',' << ratio << ',' << law << ',' << theory << ',' << hertz << '\n';
  };
  // Loading: no force until the surfaces touch, then the jump to -(8/9) F_c and the JKR branch.
  for (int k = 0; k <= n / 4; ++k) row(0, -2.0 + 2.0 * k / (n / 4), false);
  for (int k = 0; k <= n; ++k) row(0, top * k / n, true);
  // Unloading: back along the JKR branch into tension down to delta = -delta_c, then free.
  for (int k = 0; k <= n; ++k) {
    const double ratio = top - (top + 1.0) * k / n;
    row(1, ratio, true);
  }
  row(1, -1.0, false);
  row(1, -2.0, false);
  const double x_pull = std::pow(4.0, -1.0 / 3.0);
  const double depth = -jkr.respond(a0 * a0 / (3.0 * c.radius), c).energy / (fc * dc);
  std::fprintf(summary, "jkr_force: well depth at a = a0 (relative to touching) = %.4f F_c delta_c\n", depth);
  std::fprintf(summary,
               "jkr_force: max |F_law - F_eq5(eq2)| / F_c = %.2e over %d points; a0 = %.5f, F_c = %.5f, delta_c = %.5e;"
               " force-controlled break at delta/delta_c = %.4f\n",
               worst, 2 * n + 2, a0, fc, dc, std::cbrt(6.0) * (2.0 * x_pull * x_pull - 4.0 / 3.0 * std::sqrt(x_pull)));
}

// ---------------------------------------------------------------------------------------------
// 3. Energy budget of a relaxed BCCA cluster hitting a wall with every contact law on.

void energy_budget(const std::filesystem::path& dir, std::FILE* summary) {
  const Cluster built = ballistic_cluster_cluster_aggregation({.primary_count = 64}, 20240611);
  ContactModelSpec jkr;
  const RelaxationResult relaxed = relax_cluster(particles_from_cluster(built, unit_density), {unit_material()}, jkr);
  std::fprintf(summary, "energy: relaxed 64-primary BCCA cluster in %lld steps, converged %d, %zu contacts\n",
               static_cast<long long>(relaxed.steps), relaxed.converged ? 1 : 0, relaxed.contacts);

  const ContactModelSpec spec = testing::full_model();
  const SimulationSettings settings = testing::bonded();
  const Wall wall{};
  Particles start = place_for_impact(relaxed.particles, Rotation{}, wall, 0.05, {0.0, 0.0, -0.5});
  Simulation sim(std::move(start), {unit_material()}, {wall}, spec, settings);
  const double balance0 = sim.energy().balance();
  const double kinetic0 = sim.energy().kinetic();
  std::ofstream out = open(dir, "energy.csv");
  out << "step,time,kinetic,rotational_kinetic,contact_elastic,damping,friction,rolling,twisting,breaking,"
         "stiffness_work,balance_error,contacts\n";
  // 168 tau: the cluster has come to rest on the wall (4000 steps of the step before the
  // automatic step resolved the break overlap, docs/MODEL.md 9.2), sampled 40 times.
  const double duration = 168.0;
  const auto every = static_cast<std::int64_t>(std::ceil(duration / sim.time_step() / 40.0));
  const std::int64_t steps = 40 * every;
  double worst = 0.0, deepest_wall = 0.0, deepest_pair = 0.0;
  const auto track_overlaps = [&] {
    const Particles& q = sim.particles();
    for (std::size_t i = 0; i < q.size(); ++i) {
      deepest_wall = std::max(deepest_wall, q.radius[i] - wall.gap(q.position[i]));
      for (std::size_t j = i + 1; j < q.size(); ++j)
        deepest_pair = std::max(deepest_pair, q.radius[i] + q.radius[j] - norm(q.position[i] - q.position[j]));
    }
  };
  for (std::int64_t s = 0; s <= steps; s += every) {
    for (std::int64_t k = 0; k < (s > 0 ? every : 0); ++k) {
      sim.step();
      track_overlaps();
    }
    const EnergyBudget e = sim.energy();
    const double error = e.balance() - balance0;
    worst = std::max(worst, std::fabs(error));
    const DissipationTally& d = e.dissipation;
    out << s << ',' << sim.time() << ',' << e.kinetic() << ',' << e.rotational_kinetic << ',' << e.contact_elastic
        << ',' << d.damping << ',' << d.friction << ',' << d.rolling << ',' << d.twisting << ',' << d.breaking << ','
        << d.stiffness_work << ',' << error << ',' << sim.contacts().size() << '\n';
  }
  const EnergyBudget e = sim.energy();
  Vec3 momentum;
  double mass = 0.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) {
    momentum += sim.particles().mass[i] * sim.particles().velocity[i];
    mass += sim.particles().mass[i];
  }
  const Vec3 drift = momentum / mass;
  std::fprintf(summary, "energy: final centre-of-mass velocity (%.3e, %.3e, %.3e) d/tau, kinetic of it %.3e E_kin0\n",
               drift.x, drift.y, drift.z, 0.5 * mass * norm2(drift) / kinetic0);
  std::fprintf(summary, "energy: deepest overlap with the wall %.4f d, between primaries %.4f d\n", deepest_wall,
               deepest_pair);
  std::fprintf(summary,
               "energy: dt = %.4e tau (period %.4f tau), %lld steps; E_kin0 = %.5f; final kinetic %.4f, elastic %.4f,"
               " damping %.4f, friction %.4f, rolling %.4f, twisting %.4f, breaking %.4f, stiffness work %.4f"
               " (all / E_kin0); max |balance error| / E_kin0 = %.3e, final %.3e; contacts broken %llu, made %llu\n",
               sim.time_step(), sim.time_step_estimate().period, static_cast<long long>(steps), kinetic0,
               e.kinetic() / kinetic0, e.contact_elastic / kinetic0, e.dissipation.damping / kinetic0,
               e.dissipation.friction / kinetic0, e.dissipation.rolling / kinetic0, e.dissipation.twisting / kinetic0,
               e.dissipation.breaking / kinetic0, e.dissipation.stiffness_work / kinetic0, worst / kinetic0,
               (e.balance() - balance0) / kinetic0, static_cast<unsigned long long>(sim.pair_events().broken),
               static_cast<unsigned long long>(sim.pair_events().made));
}

// ---------------------------------------------------------------------------------------------
// 4. Time-step convergence of the energy error of a bonded JKR dimer.

void conservation(const std::filesystem::path& dir, std::FILE* summary) {
  ContactModelSpec spec;
  spec.tangential = false;
  Particles p;
  p.add({0.0, 0.0, 0.0}, 0.5, unit_density);
  p.add({0.0, 0.0, 0.99}, 0.5, unit_density);
  p.velocity[1] = {0.0, 0.0, 0.01};
  std::ofstream out = open(dir, "conservation.csv");
  // E is measured from touching (delta = 0), so E0 < 0 for a bonded pair: the error is given
  // relative to |E0| and to the oscillation energy E0 - E_min (E_min: at rest at the equilibrium
  // overlap a0^2 / (3 R*), eqs 2, 4).
  const ContactConstants c = jkr_constants(false);
  const double bottom = JkrNormal{}.respond(c.equilibrium_radius * c.equilibrium_radius / (3.0 * c.radius), c).energy;
  out << "steps_per_period,time_step,max_error_over_abs_E0,max_error_over_oscillation_energy\n";
  double previous = 0.0;
  for (double steps_per_period : {25.0, 50.0, 100.0, 200.0, 400.0}) {
    SimulationSettings settings;
    settings.steps_per_period = steps_per_period;
    Simulation sim(p, {unit_material()}, {}, spec, settings);
    const double e0 = sim.energy().mechanical();
    double worst = 0.0;
    while (sim.time() < 200.0) {
      sim.step();
      worst = std::max(worst, std::fabs(sim.energy().mechanical() - e0));
    }
    if (sim.pair_events().broken != 0) throw std::runtime_error("conservation: the dimer came apart");
    const double relative = worst / std::fabs(e0);
    out << steps_per_period << ',' << sim.time_step() << ',' << relative << ',' << worst / (e0 - bottom) << '\n';
    std::fprintf(summary,
                 "conservation: %5.0f steps/period, dt = %.4e, E0 = %.4e, E0 - E_min = %.4e, max |E-E0|/|E0| = %.4e,"
                 " / (E0 - E_min) = %.4e%s\n",
                 steps_per_period, sim.time_step(), e0, e0 - bottom, relative, worst / (e0 - bottom),
                 previous > 0.0 ? (", ratio to previous " + std::to_string(relative / previous)).c_str() : "");
    previous = relative;
  }
}

// ---------------------------------------------------------------------------------------------
// 5. Radius of gyration of BCCA clusters versus N (report figure 2b).

void rg_vs_n(const std::filesystem::path& dir, std::FILE* summary) {
  std::vector<SizeRadiusSample> samples;
  std::ofstream table = open(dir, "rg_vs_n.csv");
  std::ofstream each = open(dir, "rg_samples.csv");
  table << "N,mean_Rg,std_Rg,clusters\n";
  each << "N,Rg,seed\n";
  const int per_size = 16;
  std::uint64_t seed = 5000;
  for (std::size_t n = 16; n <= 4096; n *= 2) {
    double sum = 0.0, sum2 = 0.0;
    for (int r = 0; r < per_size; ++r, ++seed) {
      const double rg = radius_of_gyration(ballistic_cluster_cluster_aggregation({.primary_count = n}, seed));
      samples.push_back({static_cast<double>(n), rg});
      each << n << ',' << rg << ',' << seed << '\n';
      sum += rg;
      sum2 += rg * rg;
    }
    const double mean = sum / per_size;
    const double variance = std::max(0.0, (sum2 - per_size * mean * mean) / (per_size - 1));
    table << n << ',' << mean << ',' << std::sqrt(variance) << ',' << per_size << '\n';
  }
  const FractalScalingFit fit = fit_fractal_scaling(samples, 0.5);
  std::ofstream fitted = open(dir, "rg_fit.csv");
  fitted << "fractal_dimension,prefactor,fractal_dimension_standard_error,samples\n";
  fitted << fit.fractal_dimension << ',' << fit.prefactor << ',' << fit.fractal_dimension_standard_error << ','
         << fit.sample_count << '\n';
  std::fprintf(summary, "rg_vs_n: D_f = %.4f +- %.4f, k_f = %.4f (N = k_f (Rg/a)^D_f, a = d/2), %zu clusters\n",
               fit.fractal_dimension, fit.fractal_dimension_standard_error, fit.prefactor, fit.sample_count);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIRECTORY\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    std::FILE* summary = std::fopen((dir / "summary.txt").c_str(), "w");
    if (!summary) throw std::runtime_error("cannot write summary.txt");
    const auto total = std::chrono::steady_clock::now();
    const auto timed = [&](const char* name, auto&& section) {
      const auto start = std::chrono::steady_clock::now();
      section(dir, summary);
      std::fprintf(summary, "time: %s %.1f s\n", name, seconds_since(start));
      std::fflush(summary);
      std::fprintf(stderr, "validation_data: %s done (%.1f s)\n", name, seconds_since(start));
    };
    timed("jkr_force", jkr_force);
    timed("conservation", conservation);
    timed("restitution", restitution);
    timed("energy", energy_budget);
    timed("rg_vs_n", rg_vs_n);
    std::fprintf(summary, "time: total %.1f s\n", seconds_since(total));
    std::fclose(summary);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "validation_data: %s\n", e.what());
    return 1;
  }
  return 0;
}
