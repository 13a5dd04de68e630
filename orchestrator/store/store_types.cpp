#include "orchestrator/store/store_types.hpp"

#include <array>
#include <utility>

namespace aerobreak {
namespace {

constexpr std::array<std::pair<CaseStatus, std::string_view>, 5> kStatusNames{{
    {CaseStatus::queued, "queued"},
    {CaseStatus::running, "running"},
    {CaseStatus::done, "done"},
    {CaseStatus::failed, "failed"},
    {CaseStatus::cancelled, "cancelled"},
}};

}  // namespace

std::string_view to_string(CaseStatus status) {
  for (const auto& [value, name] : kStatusNames)
    if (value == status) return name;
  return "unknown";
}

std::optional<CaseStatus> parse_case_status(std::string_view text) {
  for (const auto& [value, name] : kStatusNames)
    if (name == text) return value;
  return std::nullopt;
}

std::string_view to_string(AttemptEnd end) {
  switch (end) {
    case AttemptEnd::done:
      return "done";
    case AttemptEnd::invalid:
      return "invalid";
    case AttemptEnd::error:
      return "error";
    case AttemptEnd::wall_time:
      return "wall_time";
    case AttemptEnd::lost:
      return "lost";
    case AttemptEnd::interrupted:
      return "interrupted";
  }
  return "error";
}

std::size_t GridPointOutcomes::finished() const {
  std::size_t total = 0;
  for (const auto& [outcome, count] : outcomes) total += count;
  return total;
}

std::size_t GridPointOutcomes::trials_for(const std::string& outcome) const {
  const auto undetermined = outcomes.find("undetermined");
  const std::size_t unsettled = undetermined == outcomes.end() ? 0 : undetermined->second;
  return outcome == "undetermined" ? finished() : finished() - unsettled;
}

std::optional<MeanEstimate> mean_estimate(const Moments& moments) {
  return streamed_mean_estimate(moments.count, moments.sum, moments.squared_deviations);
}

}  // namespace aerobreak
