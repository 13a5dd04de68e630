#include "engine/impact/outcome.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace aerobreak {
namespace {

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g %%", 100.0 * share);
  return text;
}

// Fills the fractions, shares and re-entrained fragments of `c`.
void measure(const std::vector<FragmentFate>& fragments, Classification& c) {
  double mass = 0.0, on_wall = 0.0, heaviest_off = 0.0;
  std::size_t primaries = 0, largest = 0, pieces_on_wall = 0;
  for (std::size_t k = 0; k < fragments.size(); ++k) {
    const FragmentFate& f = fragments[k];
    mass += f.mass;
    primaries += f.primaries;
    largest = std::max(largest, f.primaries);
    if (f.on_wall) {
      on_wall += f.mass;
      ++pieces_on_wall;
    } else {
      heaviest_off = std::max(heaviest_off, f.mass);
      c.reentrained.push_back(k);
    }
  }
  c.retained_mass_fraction = on_wall / mass;
  c.reentrained_mass_fraction = 1.0 - c.retained_mass_fraction;
  if (c.reentrained.empty()) c.reentrained_mass_fraction = 0.0;
  c.largest_fragment_share = static_cast<double>(largest) / static_cast<double>(primaries);
  c.largest_reentrained_share = heaviest_off / mass;
  c.fractured_on_wall = pieces_on_wall > 1;
}

}  // namespace

std::string to_string(ImpactOutcome outcome) {
  switch (outcome) {
    case ImpactOutcome::stick:
      return "stick";
    case ImpactOutcome::bounce:
      return "bounce";
    case ImpactOutcome::break_up:
      return "break-up";
    case ImpactOutcome::undetermined:
      return "undetermined";
  }
  return "undetermined";
}

std::optional<ImpactOutcome> parse_outcome(std::string_view text) {
  for (const ImpactOutcome outcome : kImpactOutcomes)
    if (text == to_string(outcome)) return outcome;
  return std::nullopt;
}

std::vector<std::string> outcome_names() {
  std::vector<std::string> names;
  for (const ImpactOutcome outcome : kImpactOutcomes) names.push_back(to_string(outcome));
  return names;
}

std::string outcome_names_text() {
  const auto names = outcome_names();
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return text;
}

Classification classify(const std::vector<FragmentFate>& fragments, bool settled, const OutcomeThresholds& thresholds) {
  if (!(thresholds.bounce_share > 0.5 && thresholds.bounce_share <= 1.0))
    throw std::invalid_argument("classify: the bounce share must be in (0.5, 1]");
  Classification c;
  double mass = 0.0;
  for (const FragmentFate& f : fragments) mass += f.mass;
  if (fragments.empty() || !(mass > 0.0)) {
    c.reason = "no primaries";
    return c;
  }
  measure(fragments, c);
  if (!settled) {
    c.reason = "the time limit came before the outcome settled";
    return c;
  }
  const std::string left = std::to_string(c.reentrained.size()) + " fragment" + (c.reentrained.size() == 1 ? "" : "s") +
                           " left the wall with " + percent(c.reentrained_mass_fraction) + " of the mass";
  if (c.reentrained.empty()) {
    c.outcome = ImpactOutcome::stick;
    c.reason =
        c.fractured_on_wall ? "nothing left the wall, which holds the cluster in pieces" : "nothing left the wall";
  } else if (c.largest_reentrained_share >= thresholds.bounce_share) {
    c.outcome = ImpactOutcome::bounce;
    c.reason = left + "; the heaviest holds " + percent(c.largest_reentrained_share) + ", at least the bounce share " +
               percent(thresholds.bounce_share);
  } else {
    c.outcome = ImpactOutcome::break_up;
    c.reason = left + "; the heaviest holds " + percent(c.largest_reentrained_share) + ", below the bounce share " +
               percent(thresholds.bounce_share);
  }
  return c;
}

}  // namespace aerobreak
