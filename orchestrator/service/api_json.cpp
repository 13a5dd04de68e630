#include "orchestrator/service/api_json.hpp"

#include "orchestrator/study/field_units.hpp"
#include "orchestrator/study/study_axes.hpp"
#include "orchestrator/study/study_search.hpp"
#include "orchestrator/study/study_units.hpp"

namespace aerobreak {
namespace {

template <typename T>
nlohmann::ordered_json optional_json(const std::optional<T>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json text_or_null(const std::string& text) {
  return text.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(text);
}

// One axis of a study, a grid axis with its values or the search's with its range (StudyAxis).
nlohmann::ordered_json study_axis_json(const AxisDescription& axis, const std::string& role,
                                       nlohmann::ordered_json values, nlohmann::ordered_json range) {
  nlohmann::ordered_json json = axis_description_json(axis);
  json["role"] = role;
  json["values"] = std::move(values);
  json["range"] = std::move(range);
  return json;
}

}  // namespace

nlohmann::ordered_json axis_description_json(const AxisDescription& axis) {
  return {{"name", axis.name},          {"pointer", axis.pointer}, {"alias", text_or_null(axis.alias)},
          {"label", axis.label},        {"symbol", axis.symbol},   {"unit", text_or_null(axis.unit)},
          {"log_scale", axis.log_scale}};
}

nlohmann::ordered_json study_axes_json(const nlohmann::ordered_json& study_document) {
  const std::string system = study_unit_system(study_document);
  const nlohmann::ordered_json grid_axes = study_document.value("axes", nlohmann::ordered_json::object());
  std::vector<SchemaViolation> unused;  // the stored document passed parse_study
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  std::vector<std::string> pointers;
  for (const auto& axis : read_axes(grid_axes, unused)) {
    pointers.push_back(axis.pointer);
    axes.push_back(study_axis_json(describe_axis(axis.name, system), "grid", axis.values, nullptr));
  }
  if (const auto search = study_document.find("search"); search != study_document.end()) {
    const BoundarySearchSpec spec = read_search_spec(*search, pointers, unused);
    AxisDescription axis = describe_axis(spec.axis, system);
    axis.log_scale = spec.logarithmic;  // the scale the search places its cases in
    axes.push_back(study_axis_json(axis, "search", nullptr, {spec.from, spec.to}));
  }
  return axes;
}

nlohmann::ordered_json to_json(const StudyRecord& study, bool with_document) {
  nlohmann::ordered_json json{{"id", study.id},
                              {"name", study.name},
                              {"description", study.description},
                              {"status", study.status},
                              {"hash", study.hash},
                              {"cases", study.case_count},
                              {"max_attempts", study.max_attempts},
                              {"case_wall_time", study.case_wall_time},
                              {"created_at", study.created_at},
                              {"cancelled_at", optional_json(study.cancelled_at)},
                              {"units", units_json(study_unit_system(study.document))},
                              {"axes", study_axes_json(study.document)}};
  if (with_document) json["document"] = study.document;
  return json;
}

nlohmann::ordered_json to_json(const StudyProgress& progress) {
  nlohmann::ordered_json counts = nlohmann::ordered_json::object();
  for (const auto& [status, count] : progress.by_status) counts[status] = count;
  return {{"study", progress.study_id},
          {"total", progress.total},
          {"counts", counts},
          {"complete", progress.complete},
          {"search_groups", progress.search_groups},
          {"searching_groups", progress.searching_groups},
          {"cases_per_hour", progress.cases_per_hour},
          {"seconds_left", optional_json(progress.seconds_left)},
          {"first_started_at", optional_json(progress.first_started_at)},
          {"last_finished_at", optional_json(progress.last_finished_at)}};
}

nlohmann::ordered_json to_json(const CaseRecord& record) {
  return {{"id", record.id},
          {"hash", record.hash},
          {"grid_point", record.grid_point},
          {"replicate", record.replicate},
          {"status", record.status},
          {"outcome", optional_json(record.outcome)},
          {"attempts", record.attempts},
          {"failures", record.failures},
          {"max_attempts", record.max_attempts},
          {"wall_time_limit", record.wall_time_limit},
          {"job", optional_json(record.job_id)},
          {"worker", optional_json(record.worker)},
          {"queued_at", record.queued_at},
          {"started_at", optional_json(record.started_at)},
          {"finished_at", optional_json(record.finished_at)},
          {"error", optional_json(record.error)}};
}

nlohmann::ordered_json to_json(const ResultRecord& record) {
  return {{"case", record.case_id},
          {"hash", record.hash},
          {"grid_point", record.grid_point},
          {"replicate", record.replicate},
          {"attempt", record.attempt},
          {"outcome", record.outcome},
          {"restitution", optional_json(record.restitution)},
          {"largest_fragment_share", optional_json(record.largest_fragment_share)},
          {"fragment_count", optional_json(record.fragment_count)},
          {"retained_mass_fraction", optional_json(record.retained_mass_fraction)},
          {"reentrained_mass_fraction", optional_json(record.reentrained_mass_fraction)},
          {"damage_ratio", optional_json(record.damage_ratio)},
          {"fractured_on_wall", optional_json(record.fractured_on_wall)},
          {"small_strain_exceeded", optional_json(record.small_strain_exceeded)},
          {"energy_per_contact", optional_json(record.energy_per_contact)},
          {"energy_over_rolling", optional_json(record.energy_over_rolling)},
          {"initial_contacts", optional_json(record.initial_contacts)},
          {"impact_energy", optional_json(record.impact_energy)},
          {"wall_clock_seconds", optional_json(record.wall_clock_seconds)},
          {"data_file", optional_json(record.data_file)},
          {"committed_at", record.committed_at}};
}

nlohmann::ordered_json to_json(const CaseDetail& detail, const std::optional<DataFileCheck>& data_file_check) {
  nlohmann::ordered_json json = to_json(detail.record);
  const std::string system = case_unit_system(detail.document);
  json["units"] = units_json(system);
  auto& axes = json["axes"] = nlohmann::ordered_json::array();
  for (const auto& [name, value] : detail.record.grid_point.items())
    axes.push_back(axis_description_json(describe_axis(name, system)));
  json["document"] = detail.document;
  auto& attempts = json["attempt_history"] = nlohmann::ordered_json::array();
  for (const auto& attempt : detail.attempts) {
    attempts.push_back({{"attempt", attempt.attempt},
                        {"job", optional_json(attempt.job_id)},
                        {"worker", optional_json(attempt.worker)},
                        {"started_at", attempt.started_at},
                        {"ended_at", optional_json(attempt.ended_at)},
                        {"outcome", optional_json(attempt.outcome)},
                        {"error", optional_json(attempt.error)}});
  }
  auto& fragments = json["fragments"] = nlohmann::ordered_json::array();
  for (const auto& fragment : detail.fragments) {
    fragments.push_back({{"rank", fragment.rank},
                         {"primaries", fragment.primaries},
                         {"mass", fragment.mass},
                         {"on_wall", fragment.on_wall},
                         {"normal_velocity", optional_json(fragment.normal_velocity)},
                         {"radius_of_gyration", optional_json(fragment.radius_of_gyration)}});
  }
  json["data_file"] = optional_json(detail.data_file);
  json["data_file_check"] = nullptr;
  if (data_file_check) {
    const auto& digest = detail.data_file_digest;
    json["data_file_check"] = {
        {"state", std::string(to_string(data_file_check->state))},
        {"problem", text_or_null(data_file_check->problem)},
        {"size", digest.size >= 0 ? nlohmann::ordered_json(digest.size) : nlohmann::ordered_json(nullptr)},
        {"sha256", text_or_null(digest.sha256)}};
  }
  json["result"] = detail.result ? *detail.result : nlohmann::ordered_json(nullptr);
  return json;
}

nlohmann::ordered_json to_json(const JobRecord& job) {
  return {{"id", job.id},
          {"command", job.command},
          {"ranks", job.ranks},
          {"pid", optional_json(job.pid)},
          {"started_at", job.started_at},
          {"ended_at", optional_json(job.ended_at)},
          {"exit_status", optional_json(job.exit_status)},
          {"note", optional_json(job.note)}};
}

nlohmann::ordered_json to_json(const SubmissionReceipt& receipt) {
  return {
      {"id", receipt.study_id},           {"existing_study", receipt.existing_study},  {"cases", receipt.cases},
      {"new_cases", receipt.new_cases},   {"already_done", receipt.already_done},      {"requeued", receipt.requeued},
      {"recomputed", receipt.recomputed}, {"data_files_lost", receipt.data_files_lost}};
}

}  // namespace aerobreak
