#include "orchestrator/service/dashboard_endpoints.hpp"

#include <map>
#include <set>
#include <string>

#include "orchestrator/app/study_results_json.hpp"
#include "orchestrator/fitting/estimate_json.hpp"
#include "orchestrator/service/api_json.hpp"
#include "orchestrator/service/case_file_download.hpp"
#include "orchestrator/service/grid_filter.hpp"
#include "orchestrator/service/http_support.hpp"
#include "orchestrator/service/versioned_documents.hpp"

namespace aerobreak {
namespace {

constexpr std::size_t kMaxProgressPage = 100;
constexpr std::size_t kMaxFragmentGridPoints = 1000;

// Each axis (in the study's order) with its distinct values, sorted.
nlohmann::ordered_json axes_json(const std::vector<GridPointStatistics>& cells) {
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  if (cells.empty()) return axes;
  for (const auto& [axis, first] : cells.front().outcomes.grid_point.items()) {
    std::set<nlohmann::ordered_json> values;
    for (const auto& cell : cells) values.insert(cell.outcomes.grid_point.at(axis));
    axes.push_back({{"name", axis}, {"values", nlohmann::ordered_json(values)}});
  }
  return axes;
}

nlohmann::ordered_json grid_json(std::int64_t study, const std::vector<GridPointStatistics>& cells) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& cell : cells) {
    auto row = grid_point_outcomes_json(cell);
    row["restitution"] = mean_json(mean_estimate(cell.restitution));
    row["fragment_count"] = mean_json(mean_estimate(cell.fragment_count));
    row["largest_fragment_share"] = mean_json(mean_estimate(cell.largest_fragment_share));
    rows.push_back(std::move(row));
  }
  return {{"study", study}, {"confidence", 0.95}, {"axes", axes_json(cells)}, {"grid_points", rows}};
}

CaseFilter case_filter(const httplib::Request& request, Store& store, GridPointCache& grid, std::int64_t study_id) {
  CaseFilter filter;
  filter.status = status_parameter(request);
  filter.outcome = outcome_parameter(request);
  const AxisFilter axes(request);
  if (!axes.empty()) filter.grid_keys = axes.matching_keys(*grid.points(store, study_id));
  return filter;
}

nlohmann::ordered_json case_row_json(const CaseRecord& record) {
  auto json = to_json(record);
  const auto optional = [](const auto& value) {
    return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
  };
  json["restitution"] = optional(record.restitution);
  json["retained_mass_fraction"] = optional(record.retained_mass_fraction);
  json["fragment_count"] = optional(record.fragment_count);
  json["damage_ratio"] = optional(record.damage_ratio);
  json["fractured_on_wall"] = optional(record.fractured_on_wall);
  json["small_strain_exceeded"] = optional(record.small_strain_exceeded);
  return json;
}

nlohmann::ordered_json fragment_sizes_json(Store& store, GridPointCache& grid, const StudyRecord& study,
                                           const AxisFilter& axes) {
  const auto points_held = grid.points(store, study.id);
  const auto& points = *points_held;
  const auto keys = axes.matching_keys(points);
  if (keys.size() > kMaxFragmentGridPoints)
    throw RequestError{400, std::to_string(keys.size()) + " grid points match; narrow them to at most " +
                                std::to_string(kMaxFragmentGridPoints) + " with axis.NAME=VALUE"};
  std::map<std::string, const nlohmann::ordered_json*> grid_point_of;
  for (const auto& [key, grid_point] : points) grid_point_of[key] = &grid_point;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& point : store.fragment_sizes(study.id, keys)) {
    nlohmann::ordered_json sizes = nlohmann::ordered_json::array();
    for (const auto& [primaries, count] : point.sizes) sizes.push_back({primaries, count});
    rows.push_back({{"grid_point", *grid_point_of.at(point.grid_key)}, {"results", point.results}, {"sizes", sizes}});
  }
  return {{"study", study.id}, {"grid_points", rows}};
}

}  // namespace

std::string grid_document(Store& store, std::int64_t study) {
  return grid_json(study, store.grid_statistics(study)).dump();
}

namespace endpoint {

void list_study_progress(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  PageRequest page;
  page.limit = unsigned_parameter(request, "limit", 20, kMaxProgressPage);
  page.offset = unsigned_parameter(request, "offset", 0, std::size_t{1} << 40);
  const auto studies = e.store.studies(page);
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  for (const auto& study : studies.items) {
    auto json = to_json(study, false);
    json["progress"] = to_json(*e.store.progress(study.id));
    items.push_back(std::move(json));
  }
  send_json(response, 200,
            {{"total", studies.total}, {"limit", page.limit}, {"offset", page.offset}, {"items", items}});
}

void get_study_grid(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  e.grids.serve(e.store, path_id(request), request, response);
}

void get_study_case_table(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  const auto filter = case_filter(request, e.store, e.grid_points, study.id);
  const auto page = page_request(request, e.options);
  const auto cases = e.store.cases(study.id, filter, page);
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  for (const auto& record : cases.items) items.push_back(case_row_json(record));
  send_json(response, 200, {{"total", cases.total}, {"limit", page.limit}, {"offset", page.offset}, {"items", items}});
}

void get_study_fragment_sizes(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto study = existing_study(e.store, path_id(request));
  send_json(response, 200, fragment_sizes_json(e.store, e.grid_points, study, AxisFilter(request)));
}

void get_case_data(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  send_case_file(response, e.store, path_id(request), e.options.data_directory, e.data_files);
}

}  // namespace endpoint

}  // namespace aerobreak
