#include "engine/impact/settle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <stdexcept>

#include "engine/dem/simulation.hpp"

namespace aerobreak {
namespace {

std::string describe_fragment(std::size_t k, const Fragment& f) {
  return "fragment " + std::to_string(k + 1) + " (" + std::to_string(f.size) + " primar" +
         (f.size == 1 ? "y" : "ies") + ")";
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

}  // namespace

std::string unsettled_reason(const std::vector<Fragment>& fragments, const std::vector<Vec3>& mean_velocity,
                             const std::vector<double>& lowest_gap_before, const Vec3& wall_normal,
                             double rest_speed) {
  const Vec3 n = wall_normal / norm(wall_normal);
  for (std::size_t k = 0; k < fragments.size(); ++k) {
    const Fragment& f = fragments[k];
    const double mean_normal = dot(mean_velocity[k], n);
    if (f.on_wall()) {
      if (std::abs(mean_normal) > rest_speed)
        return describe_fragment(k, f) + " touches the wall and is not at rest (mean normal speed " +
               number(mean_normal) + ", rest below " + number(rest_speed) + ")";
    } else if (!(mean_normal > 0.0 && f.normal_velocity > 0.0)) {
      return describe_fragment(k, f) + " is off the wall but not moving away from it (normal speed " +
             number(f.normal_velocity) + ")";
    } else if (!(f.lowest_gap > lowest_gap_before[k])) {
      return describe_fragment(k, f) + " is moving away from the wall but its lowest point is not";
    }
  }
  // Two fragments can still meet if their centres approach and, moving on as they do, would pass
  // closer than their bounding spheres allow. Fragments both resting on the wall are left out.
  for (std::size_t a = 0; a < fragments.size(); ++a)
    for (std::size_t b = a + 1; b < fragments.size(); ++b) {
      if (fragments[a].on_wall() && fragments[b].on_wall()) continue;
      const Vec3 separation = fragments[b].centre_of_mass - fragments[a].centre_of_mass;
      const Vec3 relative = mean_velocity[b] - mean_velocity[a];
      const double approach = dot(separation, relative);
      if (approach >= 0.0) continue;
      const Vec3 miss = separation - (approach / norm2(relative)) * relative;
      const double reach = fragments[a].bounding_radius + fragments[b].bounding_radius;
      if (norm2(miss) <= reach * reach)
        return describe_fragment(a, fragments[a]) + " and " + describe_fragment(b, fragments[b]) +
               " are approaching each other";
    }
  return {};
}

SettleMonitor::SettleMonitor(double quiet_window, double rest_speed)
    : quiet_window_(quiet_window), rest_speed_(rest_speed) {
  if (!(quiet_window > 0.0)) throw std::invalid_argument("settle: quiet_window must be > 0");
  if (!(rest_speed >= 0.0)) throw std::invalid_argument("settle: rest_speed must be >= 0");
}

void SettleMonitor::start_window(const Simulation& simulation, std::uint64_t events) {
  started_ = true;
  events_ = events;
  window_start_ = simulation.time();
  positions_ = simulation.particles().position;
}

bool SettleMonitor::update(const Simulation& simulation) {
  if (settled_) return true;
  const std::uint64_t events = simulation.pair_events().made + simulation.pair_events().broken +
                               simulation.wall_events().made + simulation.wall_events().broken;
  if (!started_ || events != events_) {
    start_window(simulation, events);
    return false;
  }
  const double elapsed = simulation.time() - window_start_;
  if (elapsed < quiet_window_) return false;

  ++judgements_;
  // No contact was made or broken in the window, so the fragments now are those at its start.
  const FragmentAnalysis now = find_fragments(simulation);
  const Particles& p = simulation.particles();
  const Wall wall = simulation.walls().empty() ? Wall{} : simulation.walls().front();
  const Vec3 n = wall.normal / norm(wall.normal);
  std::vector<Vec3> mean_velocity(now.fragments.size());
  std::vector<double> lowest_before(now.fragments.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::uint32_t k = now.fragment_of[i];
    mean_velocity[k] += p.mass[i] * (p.position[i] - positions_[i]);
    lowest_before[k] = std::min(lowest_before[k], dot(positions_[i] - wall.point, n) - p.radius[i]);
  }
  for (std::size_t k = 0; k < now.fragments.size(); ++k)
    mean_velocity[k] = mean_velocity[k] / (now.fragments[k].mass * elapsed);

  last_reason_ = unsettled_reason(now.fragments, mean_velocity, lowest_before, n, rest_speed_);
  judged_ = now;
  judged_mean_velocity_ = mean_velocity;
  if (last_reason_.empty()) {
    settled_ = true;
    settled_at_ = simulation.time();
    return true;
  }
  start_window(simulation, events);
  return false;
}

}  // namespace aerobreak
