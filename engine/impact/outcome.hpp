#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aerobreak {

// The outcome classes of an impact (docs/IMPACT.md): stick = nothing leaves the wall; bounce = the
// cluster leaves it intact; break-up = mass leaves it in pieces; undetermined = the time limit came
// first (never counted as any of the three). The one vocabulary of outcomes: the engine's results,
// the store (its summary columns in this order), the statistics, the API's parameters and the
// command line all name and order them from here.
enum class ImpactOutcome { stick, bounce, break_up, undetermined };
inline constexpr ImpactOutcome kImpactOutcomes[] = {ImpactOutcome::stick, ImpactOutcome::bounce,
                                                    ImpactOutcome::break_up, ImpactOutcome::undetermined};
inline constexpr ImpactOutcome kDeterminedOutcomes[] = {ImpactOutcome::stick, ImpactOutcome::bounce,
                                                        ImpactOutcome::break_up};

// "stick", "bounce", "break-up", "undetermined" (the names results use).
std::string to_string(ImpactOutcome outcome);
// The outcome of that name; nullopt for any other text.
std::optional<ImpactOutcome> parse_outcome(std::string_view text);
// Every name in kImpactOutcomes' order, and the same as one phrase ("stick, bounce, break-up or
// undetermined") for error messages.
std::vector<std::string> outcome_names();
std::string outcome_names_text();

// What the outcome rule reads of one fragment: its primaries, its mass, whether it touches the
// wall, and its centre-of-mass velocity (normal component > 0: moving away from the wall). The
// same fields are stored per fragment, so that stored results can be classified again.
struct FragmentFate {
  std::size_t primaries = 0;
  double mass = 0.0;
  bool on_wall = false;
  double normal_velocity = 0.0;
  double speed = 0.0;
};

struct OutcomeThresholds {
  // Bounce: the largest fragment off the wall holds at least this share of the mass (the case's
  // /classification/largest_fragment_share).
  double bounce_share = 0.9;
};

struct Classification {
  ImpactOutcome outcome = ImpactOutcome::undetermined;
  bool fractured_on_wall = false;          // more than one fragment touches the wall
  double retained_mass_fraction = 0.0;     // mass of the fragments touching the wall / all
  double reentrained_mass_fraction = 0.0;  // mass of the fragments off it / all
  double largest_fragment_share = 0.0;     // primaries of the largest fragment (on or off the wall) / all
  double largest_reentrained_share = 0.0;  // mass of the heaviest fragment off the wall / all
  std::vector<std::size_t> reentrained;    // indices (into the fragments given) of those off the wall
  std::string reason;                      // one sentence: which rule decided
};

// The outcome by what leaves the wall (docs/IMPACT.md section 5), for the fragments of a settled
// impact (`settled` false: undetermined, whatever the fragments look like; the fractions are then
// those of the last state):
//   stick     no fragment is off the wall (a deposit cracked into several pieces on the wall is
//             still a stick, with fractured_on_wall set);
//   bounce    the heaviest fragment off the wall holds at least bounce_share of the mass; the rest
//             (at most 1 - bounce_share) may stay on the wall or leave as debris;
//   break-up  otherwise: mass leaves the wall, and not as one piece holding bounce_share of it.
// In a settled state every fragment off the wall moves away from it (docs/IMPACT.md section 4).
Classification classify(const std::vector<FragmentFate>& fragments, bool settled,
                        const OutcomeThresholds& thresholds = {});

}  // namespace aerobreak
