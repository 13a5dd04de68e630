// The store's per-grid-point queries: outcome counts (from the summaries), moments of the results'
// scalar quantities and fragment-size counts, aggregated by SQLite so that a study of 100,000 cases
// answers in one pass.
#include <array>
#include <map>
#include <optional>
#include <string>

#include "engine/impact/outcome.hpp"
#include "orchestrator/store/store.hpp"
#include "orchestrator/store/store_read_connection.hpp"

namespace aerobreak {
namespace {

// Each result quantity with moments: its column (an SQL expression) and where it goes. What the
// outcome fixes is averaged over the determined results (an undetermined one's state is not final,
// as in the fits: docs/CORRELATIONS.md); the restitution over the bounces only: that of a stick or
// a break-up (the largest fragment's, often negative on the wall) is not a coefficient of
// restitution of the cluster. The energy per contact, set by the impact, over every result.
struct MomentColumn {
  std::string_view column;
  Moments GridPointStatistics::*moments;
};
constexpr std::array<MomentColumn, 6> kMomentColumns{{
    {"(CASE WHEN r.outcome != 'undetermined' THEN r.retained_mass_fraction END)",
     &GridPointStatistics::retained_mass_fraction},
    {"(CASE WHEN r.outcome = 'bounce' THEN r.restitution END)", &GridPointStatistics::restitution},
    {"(CASE WHEN r.outcome != 'undetermined' THEN r.fragment_count END)", &GridPointStatistics::fragment_count},
    {"(CASE WHEN r.outcome != 'undetermined' THEN r.largest_fragment_share END)",
     &GridPointStatistics::largest_fragment_share},
    {"(CASE WHEN r.outcome != 'undetermined' THEN r.damage_ratio END)", &GridPointStatistics::damage_ratio},
    {"r.energy_per_contact", &GridPointStatistics::energy_per_contact},
}};

// Results counted per grid point by a flag: fractured on the wall, outside the small-strain range,
// and without the small-strain check (results migrated from a version-1 store).
constexpr std::array<std::string_view, 3> kFlagCounts{"sum(r.fractured_on_wall)", "sum(r.small_strain_exceeded)",
                                                      "count(*) - count(r.small_strain_exceeded)"};

// The counts come from the grid-point summaries (one row per grid point); the moments (count, sum,
// and squared deviations by Welford's update: statistics_functions.hpp) and flags from one pass
// over the study's results, grouped by grid point through study_cases_by_grid_key and read
// from the covering index results_statistics instead of the results table (migration 6). A grid
// point without results has no row in the pass: its moments read as NULL, that is 0.
std::string grid_statistics_sql() {
  std::string aggregates;
  int column = 0;
  const auto add = [&](const std::string& expression) {
    aggregates += ", " + expression + " AS m" + std::to_string(column++);
  };
  for (const auto& [name, member] : kMomentColumns) {
    const std::string value(name);
    add("count(" + value + ")");
    add("total(" + value + ")");
    add("squared_deviations(" + value + ")");
  }
  for (const auto flag : kFlagCounts) add(std::string(flag));
  std::string sql = "SELECT g.grid_key, g.grid_point, g.cases, g.failed, g.stick, g.bounce, g.break_up, g.undetermined";
  for (int i = 0; i < column; ++i) sql += ", m.m" + std::to_string(i);
  return sql + " FROM grid_point_summaries g LEFT JOIN (SELECT sc.grid_key" + aggregates +
         " FROM study_cases sc JOIN results r INDEXED BY results_statistics ON r.case_id = sc.case_id"
         " WHERE sc.study_id = ?1 GROUP BY sc.grid_key) m ON m.grid_key = g.grid_key"
         " WHERE g.study_id = ?1 ORDER BY g.position";
}

GridPointStatistics statistics_from(const SqliteStatement& row) {
  GridPointStatistics statistics;
  auto& cell = statistics.outcomes;
  cell.grid_key = row.text(0);
  cell.grid_point = nlohmann::ordered_json::parse(row.text(1));
  cell.cases = static_cast<std::size_t>(row.integer(2));
  cell.failed = static_cast<std::size_t>(row.integer(3));
  int column = 4;  // stick, bounce, break-up, undetermined: the summaries' columns in kImpactOutcomes' order
  for (const auto outcome : kImpactOutcomes)
    cell.outcomes[to_string(outcome)] = static_cast<std::size_t>(row.integer(column++));
  for (const auto& [name, member] : kMomentColumns) {
    Moments& moments = statistics.*member;
    moments.count = static_cast<std::size_t>(row.integer(column++));
    moments.sum = row.real(column++);
    moments.squared_deviations = row.real(column++);
  }
  cell.fractured_on_wall = static_cast<std::size_t>(row.integer(column++));
  cell.small_strain_exceeded = static_cast<std::size_t>(row.integer(column++));
  cell.small_strain_unchecked = static_cast<std::size_t>(row.integer(column++));
  return statistics;
}

}  // namespace

std::vector<GridPointStatistics> Store::grid_statistics(std::int64_t study_id) {
  auto db = read();
  auto statement = db->prepare(grid_statistics_sql());
  statement.bind_all(study_id);
  std::vector<GridPointStatistics> cells;
  while (statement.step()) cells.push_back(statistics_from(statement));
  return cells;
}

// The outcome and flag counts of grid_statistics, without the moments.
std::vector<GridPointOutcomes> Store::outcomes(std::int64_t study_id) {
  std::vector<GridPointOutcomes> cells;
  for (auto& statistics : grid_statistics(study_id)) cells.push_back(std::move(statistics.outcomes));
  return cells;
}

std::vector<std::pair<std::string, nlohmann::ordered_json>> Store::grid_points(std::int64_t study_id) {
  auto db = read();
  auto statement =
      db->prepare("SELECT grid_key, grid_point FROM grid_point_summaries WHERE study_id = ? ORDER BY position");
  statement.bind_all(study_id);
  std::vector<std::pair<std::string, nlohmann::ordered_json>> points;
  while (statement.step()) points.emplace_back(statement.text(0), nlohmann::ordered_json::parse(statement.text(1)));
  return points;
}

std::vector<GridPointFragments> Store::fragment_sizes(std::int64_t study_id,
                                                      const std::vector<std::string>& grid_keys) {
  auto db = read();
  const std::string keys = nlohmann::json(grid_keys).dump();
  const std::string matching = "WHERE sc.study_id = ? AND sc.grid_key IN (SELECT value FROM json_each(?)) ";
  auto results =
      db->prepare("SELECT sc.grid_key, count(*) FROM study_cases sc JOIN results r ON r.case_id = sc.case_id " +
                  matching + "GROUP BY sc.grid_key ORDER BY min(sc.position)");
  results.bind_all(study_id, keys);
  std::vector<GridPointFragments> points;
  std::map<std::string, std::size_t> index;
  while (results.step()) {
    index[results.text(0)] = points.size();
    points.push_back({results.text(0), static_cast<std::size_t>(results.integer(1)), {}});
  }
  auto sizes = db->prepare(
      "SELECT sc.grid_key, f.primaries, count(*) FROM study_cases sc JOIN fragments f "
      "ON f.case_id = sc.case_id " +
      matching + "GROUP BY sc.grid_key, f.primaries ORDER BY 1, 2");
  sizes.bind_all(study_id, keys);
  while (sizes.step()) {
    const auto found = index.find(sizes.text(0));
    if (found != index.end())
      points[found->second].sizes.emplace_back(sizes.integer(1), static_cast<std::size_t>(sizes.integer(2)));
  }
  return points;
}

std::vector<GridPointCase> Store::grid_point_cases(std::int64_t study_id) {
  auto db = read();
  // SQLite takes the bare columns of a min() aggregate from the row that holds the minimum.
  auto statement = db->prepare(
      "SELECT sc.grid_key, sc.grid_point, c.document, c.primaries, min(sc.position) FROM study_cases sc JOIN cases c "
      "ON c.id = sc.case_id WHERE sc.study_id = ? GROUP BY sc.grid_key ORDER BY min(sc.position)");
  statement.bind_all(study_id);
  std::vector<GridPointCase> points;
  while (statement.step())
    points.push_back({statement.text(0), nlohmann::ordered_json::parse(statement.text(1)),
                      nlohmann::ordered_json::parse(statement.text(2)), statement.optional_integer(3)});
  return points;
}

std::vector<GridPointFragmentMasses> Store::fragment_masses(std::int64_t study_id) {
  auto db = read();
  const std::string determined =
      "FROM study_cases sc JOIN results r ON r.case_id = sc.case_id "
      "WHERE sc.study_id = ? AND r.outcome <> 'undetermined' ";
  auto results = db->prepare("SELECT sc.grid_key, count(*), sum(r.outcome = 'break-up') " + determined +
                             "GROUP BY sc.grid_key ORDER BY min(sc.position)");
  results.bind_all(study_id);
  std::vector<GridPointFragmentMasses> points;
  std::map<std::string, std::size_t> index;
  while (results.step()) {
    index[results.text(0)] = points.size();
    points.push_back({results.text(0),
                      static_cast<std::size_t>(results.integer(1)),
                      static_cast<std::size_t>(results.integer(2)),
                      {}});
  }
  auto classes = db->prepare(
      "SELECT sc.grid_key, f.on_wall, f.primaries, count(*), total(f.mass) FROM study_cases sc "
      "JOIN results r ON r.case_id = sc.case_id JOIN fragments f ON f.case_id = r.case_id "
      "WHERE sc.study_id = ? AND r.outcome <> 'undetermined' GROUP BY 1, 2, 3 ORDER BY 1, 2, 3");
  classes.bind_all(study_id);
  while (classes.step()) {
    const auto found = index.find(classes.text(0));
    if (found == index.end()) continue;
    points[found->second].classes.push_back(
        {classes.integer(1) != 0, classes.integer(2), static_cast<std::size_t>(classes.integer(3)), classes.real(4)});
  }
  return points;
}

}  // namespace aerobreak
