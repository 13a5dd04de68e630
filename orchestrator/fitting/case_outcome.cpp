#include "orchestrator/fitting/case_outcome.hpp"

namespace aerobreak {

std::string_view to_string(Outcome outcome) {
  switch (outcome) {
    case Outcome::stick:
      return "stick";
    case Outcome::bounce:
      return "bounce";
    case Outcome::break_up:
      return "break-up";
    case Outcome::undetermined:
      break;
  }
  return "undetermined";
}

std::optional<Outcome> parse_outcome(std::string_view text) {
  for (const Outcome outcome : {Outcome::stick, Outcome::bounce, Outcome::break_up, Outcome::undetermined})
    if (text == to_string(outcome)) return outcome;
  return std::nullopt;
}

}  // namespace aerobreak
