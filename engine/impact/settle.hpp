#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/impact/fragments.hpp"

namespace aerobreak {

class Simulation;

// The state judgement of the settle criterion (docs/IMPACT.md): empty when every fragment is
// either resting on the wall or off it and moving away, and no two fragments can still meet;
// otherwise one sentence saying which fragment is not. `mean_velocity[k]` is fragment k's
// centre-of-mass velocity averaged over the quiet window, `lowest_gap_before[k]` its lowest gap to
// the wall at the window's start, `rest_speed` the largest mean normal speed that counts as rest.
std::string unsettled_reason(const std::vector<Fragment>& fragments, const std::vector<Vec3>& mean_velocity,
                             const std::vector<double>& lowest_gap_before, const Vec3& wall_normal,
                             double rest_speed);

// Watches a running impact and says when its outcome is settled: no contact (particle-particle or
// wall) has been made or broken for `quiet_window`, and then unsettled_reason() finds nothing. If
// the judgement fails, a new window starts. Call update() between steps as often as wished.
class SettleMonitor {
 public:
  SettleMonitor(double quiet_window, double rest_speed);

  bool update(const Simulation& simulation);

  bool settled() const { return settled_; }
  double settled_at() const { return settled_at_; }        // time of the successful judgement
  double quiet_since() const { return window_start_; }     // start of the last quiet window
  const std::string& last_reason() const { return last_reason_; }  // why the last judgement failed
  std::uint64_t judgements() const { return judgements_; }
  // The fragments of the last judgement and their centre-of-mass velocities averaged over its
  // quiet window (after a successful one: the settled state).
  const FragmentAnalysis& judged_fragments() const { return judged_; }
  const std::vector<Vec3>& judged_mean_velocities() const { return judged_mean_velocity_; }
  double quiet_window() const { return quiet_window_; }
  double rest_speed() const { return rest_speed_; }

 private:
  void start_window(const Simulation& simulation, std::uint64_t events);

  double quiet_window_;
  double rest_speed_;
  bool started_ = false;
  bool settled_ = false;
  double settled_at_ = 0.0;
  double window_start_ = 0.0;
  std::uint64_t events_ = 0;
  std::uint64_t judgements_ = 0;
  std::vector<Vec3> positions_;  // at the window's start
  std::string last_reason_;
  FragmentAnalysis judged_;
  std::vector<Vec3> judged_mean_velocity_;
};

}  // namespace aerobreak
