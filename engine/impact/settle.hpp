#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/impact/fragments.hpp"
#include "engine/impact/outcome.hpp"

namespace aerobreak {

class Simulation;

// The state judgement of the settle criterion (docs/IMPACT.md): empty when every fragment is
// either resting on the wall or off it and moving away, and no two fragments can still meet;
// otherwise one sentence saying which fragment is not. `mean_velocity[k]` is fragment k's
// centre-of-mass velocity averaged over the window, `lowest_gap_before[k]` its lowest gap to
// the wall at the window's start, `rest_speed` the largest mean normal speed that counts as rest.
// Two fragments resting on the wall are not tested for meeting unless `deposit_pairs`: they may
// still creep along it into each other.
std::string unsettled_reason(const std::vector<Fragment>& fragments, const std::vector<Vec3>& mean_velocity,
                             const std::vector<double>& lowest_gap_before, const Vec3& wall_normal, double rest_speed,
                             bool deposit_pairs = false);

// The state judgement of the outcome-fixed rule (docs/IMPACT.md section 4): empty when the state
// passes unsettled_reason and either is a break-up in which no fragment on the wall holds the
// bounce share of the mass (so no later lift-off can make it a bounce; fragments off the wall may
// still split, which leaves a break-up a break-up), or, `unbroken`, no contact between primaries
// broke during the window (so the fragments themselves have stopped changing); otherwise why not.
std::string outcome_open_reason(const std::vector<Fragment>& fragments, const std::vector<Vec3>& mean_velocity,
                                const std::vector<double>& lowest_gap_before, const Vec3& wall_normal,
                                double rest_speed, const OutcomeThresholds& thresholds, bool unbroken = false);

// Which rule found a run settled.
enum class SettleRule {
  quiet,          // no contact made or broken anywhere for a window, then unsettled_reason empty
  outcome_fixed,  // the deposit unchanged for a window, then outcome_open_reason empty
  fates_fixed,    // every fragment's fate fixed by energy and geometry (judge_fates, fate_rule.hpp)
};
std::string to_string(SettleRule rule);

// Watches a running impact and says when its outcome is settled, by any of three rules
// (docs/IMPACT.md section 4):
//  - quiet: no contact (particle-particle or wall) has been made or broken for `quiet_window`,
//    and then unsettled_reason() finds nothing;
//  - outcome fixed (unless turned off): over a window of the same length no wall contact was made
//    or broken and the primaries on the wall kept the same contacts among themselves (contacts
//    inside fragments in flight may change), and then outcome_open_reason() finds nothing;
//  - fates fixed (unless turned off, with the one above): at any update, judge_fates() finds
//    every fragment's fate fixed.
// A window whose judgement fails is followed by a new one. Call update() between steps as often
// as wished.
class SettleMonitor {
 public:
  SettleMonitor(double quiet_window, double rest_speed, OutcomeThresholds thresholds = {},
                bool outcome_fixed_rule = true, bool follow_rigid_turn = false);

  bool update(const Simulation& simulation);

  bool settled() const { return settled_; }
  SettleRule rule() const { return rule_; }
  double settled_at() const { return settled_at_; }                // time of the successful judgement
  double quiet_since() const { return since_; }                    // start of its window (else of the last quiet one)
  const std::string& last_reason() const { return last_reason_; }  // why the last judgement failed
  // Why a run that ends now is not settled: contacts still changing, the last objection of the
  // quiet rule's judgement, and the fates-fixed rule's objection at the last update.
  std::string open_reason(const Simulation& simulation) const;
  std::uint64_t judgements() const { return judgements_; }
  // The fragments of the last judgement and their centre-of-mass velocities averaged over its
  // window (after a successful one: the settled state).
  const FragmentAnalysis& judged_fragments() const { return judged_; }
  const std::vector<Vec3>& judged_mean_velocities() const { return judged_mean_velocity_; }
  double quiet_window() const { return quiet_window_; }
  double rest_speed() const { return rest_speed_; }

 private:
  // A window: when it began, the positions then, the contact events counted then, and (for the
  // outcome-fixed rule) the primaries on the wall and their contacts among themselves.
  struct Window {
    double start = 0.0;
    std::vector<Vec3> positions;
    std::uint64_t events = 0;
    std::uint64_t bonds_broken = 0;
    std::vector<std::uint32_t> deposit;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> deposit_contacts;
  };
  struct Judgement {
    FragmentAnalysis fragments;
    std::vector<Vec3> mean_velocity;
    std::vector<double> lowest_gap_before;
    Vec3 wall_normal;
  };
  Window open_window(const Simulation& simulation, bool with_deposit) const;
  Judgement judge(const Simulation& simulation, const Window& window) const;
  bool judge_quiet(const Simulation& simulation);
  bool judge_outcome_fixed(const Simulation& simulation);
  bool judge_fates_fixed(const Simulation& simulation);
  void settle(const Simulation& simulation, SettleRule rule, const Window& window);

  double quiet_window_;
  double rest_speed_;
  OutcomeThresholds thresholds_;
  bool outcome_fixed_rule_;
  bool follow_rigid_turn_;  // the outcome-fixed rule follows a fragment's rigid turn (swing_back_reason)
  bool started_ = false;
  bool settled_ = false;
  SettleRule rule_ = SettleRule::quiet;
  double settled_at_ = 0.0;
  double since_ = 0.0;
  std::uint64_t judgements_ = 0;
  Window quiet_;
  bool quiet_opened_by_change_ = false;  // the quiet window began because contacts changed
  Window fixed_;
  // The positions and time of the last update: a held fragment's velocity at a verdict of the
  // fates-fixed rule is its mean since then (it vibrates on the wall).
  std::vector<Vec3> last_positions_;
  double last_time_ = 0.0;
  std::string last_reason_;
  std::string last_fates_reason_;  // why the fates-fixed rule's last judgement failed
  FragmentAnalysis judged_;
  std::vector<Vec3> judged_mean_velocity_;
};

}  // namespace aerobreak
