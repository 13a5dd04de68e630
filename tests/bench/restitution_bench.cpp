// A benchmark program, not a test: the restitution and sticking-speed checks of
// tests/engine/jkr_restitution_test.cpp (a sphere on an adhesive wall and two free spheres, both
// separation rules, 1.05-10 v_stick, touching at 8 places within a step), at the adaptive
// automatic step (the default, docs/MODEL.md 9.2) and at one automatic step per run, side by side:
// per case the worst relative error of the restitution against the exact JKR loss, the steps of a
// collision and the CPU seconds of all its runs; and whether 0.99 and 1.01 v_stick stick and leave.
//
// usage: restitution_bench
#include <cmath>
#include <cstdio>

#include "engine/core/run_clock.hpp"
#include "tests/engine/jkr_cycle.hpp"

using namespace aerobreak;
using namespace aerobreak::testing::jkr_cycle;

namespace {

struct Worst {
  double error = 0.0;
  std::int64_t steps = 0;
  double cpu_seconds = 0.0;
  bool stuck = false;  // a collision that should have left stuck
};

// Worst restitution error over 8 places of touching within a step, and the steps of the last.
Worst worst_restitution(const Contact& c, JkrSeparation rule, double factor, const SimulationSettings& settings) {
  Worst w;
  const double v = factor * sticking_speed(c, rule);
  const RunClock clock;
  for (double gap : phase_gaps(c, v, rule, 8, settings)) {
    const Collision collision = collide(c, v, gap, rule, settings);
    if (collision.stuck) w.stuck = true;
    w.error = std::max(w.error, std::abs(collision.restitution / exact_restitution(c, rule, v) - 1.0));
    w.steps = collision.steps;
  }
  w.cpu_seconds = clock.elapsed().cpu_seconds;
  return w;
}

// Whether every one of 8 places of touching sticks below v_stick and leaves above it.
bool sticking_right(const Contact& c, JkrSeparation rule, const SimulationSettings& settings) {
  const double v_stick = sticking_speed(c, rule);
  for (double factor : {0.99, 1.01})
    for (double gap : phase_gaps(c, factor * v_stick, rule, 8, settings))
      if (collide(c, factor * v_stick, gap, rule, settings).stuck != (factor < 1.0)) return false;
  return true;
}

}  // namespace

int main() {
  SimulationSettings adaptive, fixed;
  fixed.adaptive_time_step = false;
  std::printf("%-12s %-12s %8s | %12s %8s %8s | %12s %8s %8s\n", "contact", "rule", "v/v_stick", "adaptive err",
              "steps", "CPU s", "one-step err", "steps", "CPU s");
  double worst[2] = {0.0, 0.0}, cpu[2] = {0.0, 0.0};
  bool sticking[2] = {true, true};
  for (const Contact& c : {sphere_on_wall(), two_spheres()})
    for (auto rule : {JkrSeparation::displacement, JkrSeparation::force}) {
      for (double factor : {1.05, 1.5, 2.0, 4.0, 10.0}) {
        const Worst a = worst_restitution(c, rule, factor, adaptive), f = worst_restitution(c, rule, factor, fixed);
        std::printf("%-12s %-12s %8.2f | %11.3f%% %8lld %8.3f | %11.3f%% %8lld %8.3f%s\n",
                    c.with_wall ? "sphere-wall" : "two spheres", name_of(rule), factor, 100.0 * a.error,
                    static_cast<long long>(a.steps), a.cpu_seconds, 100.0 * f.error, static_cast<long long>(f.steps),
                    f.cpu_seconds, a.stuck || f.stuck ? "  (a collision stuck)" : "");
        worst[0] = std::max(worst[0], a.error);
        worst[1] = std::max(worst[1], f.error);
        cpu[0] += a.cpu_seconds;
        cpu[1] += f.cpu_seconds;
      }
      sticking[0] = sticking[0] && sticking_right(c, rule, adaptive);
      sticking[1] = sticking[1] && sticking_right(c, rule, fixed);
    }
  std::printf("worst restitution error: adaptive %.3f %%, one step per run %.3f %% (the tests ask for 1 %%)\n",
              100.0 * worst[0], 100.0 * worst[1]);
  std::printf(
      "sticking speed within 1 %% (0.99 v_stick sticks, 1.01 leaves, 8 places each): adaptive %s, one step "
      "per run %s\n",
      sticking[0] ? "yes" : "NO", sticking[1] ? "yes" : "NO");
  std::printf("CPU seconds of the restitution runs: adaptive %.2f, one step per run %.2f\n", cpu[0], cpu[1]);
  return 0;
}
