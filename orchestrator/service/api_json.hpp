#pragma once
#include <nlohmann/json.hpp>

#include "orchestrator/store/data_file_check.hpp"
#include "orchestrator/store/store_types.hpp"
#include "orchestrator/study/field_units.hpp"

namespace aerobreak {

// The REST API's JSON forms of the store's records (schemas/openapi.json names each one).
// Times are Unix seconds; absent values are null. A study and a case carry their units
// (orchestrator/study/study_units.hpp).
// A study carries its axes (study_axes_json), a case the description of each axis of its grid point.
nlohmann::ordered_json to_json(const StudyRecord& study, bool with_document);
// An axis's pointer, alias, label, symbol, unit and scale (schemas/openapi.json, AxisDescription).
nlohmann::ordered_json axis_description_json(const AxisDescription& axis);
// A stored (valid) study document's axes in its order, then its search's axis (StudyAxis): each
// described (describe_axis, in the study's unit system) with its values, or the search's range.
nlohmann::ordered_json study_axes_json(const nlohmann::ordered_json& study_document);
nlohmann::ordered_json to_json(const StudyProgress& progress);
nlohmann::ordered_json to_json(const CaseRecord& record);
nlohmann::ordered_json to_json(const ResultRecord& record);
// With the check of its data file against the recorded size and SHA-256 (null without a file).
nlohmann::ordered_json to_json(const CaseDetail& detail, const std::optional<DataFileCheck>& data_file_check);
nlohmann::ordered_json to_json(const JobRecord& job);
nlohmann::ordered_json to_json(const SubmissionReceipt& receipt);
template <typename Record>
nlohmann::ordered_json page_json(const Page<Record>& page, const PageRequest& request) {
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  for (const auto& item : page.items) items.push_back(to_json(item));
  return {{"total", page.total}, {"limit", request.limit}, {"offset", request.offset}, {"items", std::move(items)}};
}

}  // namespace aerobreak
