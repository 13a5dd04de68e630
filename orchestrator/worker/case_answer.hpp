#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {

// Runs one assignment on this rank (case_runner.hpp) and returns the message that answers it: a
// "result", or a "failed" of kind "invalid" (the document fails parse_impact_case), "wall_time"
// (it ran past its wall time) or "error" (anything else thrown). Never throws for a failing case.
nlohmann::ordered_json answer_assignment(const CaseAssignment& assignment, int rank);

// The "failed" message of kind "invalid" for an assignment the broker could not read in full.
nlohmann::ordered_json answer_malformed(const MalformedAssignment& malformed, int rank);

}  // namespace aerobreak
