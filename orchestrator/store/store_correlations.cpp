// The store's side of the correlations (docs/CORRELATIONS.md): reading a study's outcomes for the
// statistics, and keeping the fitted sets.
#include <cstdio>
#include <map>
#include <unordered_map>

#include "orchestrator/store/store.hpp"
#include "orchestrator/store/store_read_connection.hpp"

namespace aerobreak {
namespace {

std::int64_t version_of(SqliteDatabase& db, std::int64_t study_id) {
  auto statement = db.prepare("SELECT result_set_version FROM study_summaries WHERE study_id = ?");
  statement.bind_all(study_id);
  return statement.step() ? statement.integer(0) : 0;
}

// The sizes of the fragments that left the wall, per case.
void add_reentrained_fragments(SqliteDatabase& db, std::int64_t study_id,
                               const std::unordered_map<std::int64_t, std::size_t>& row_of_case,
                               CaseOutcomeTable& table) {
  auto statement = db.prepare(
      "SELECT f.case_id, f.primaries FROM study_cases sc JOIN fragments f ON f.case_id = sc.case_id "
      "WHERE sc.study_id = ? AND f.on_wall = 0 ORDER BY f.case_id, f.rank");
  statement.bind_all(study_id);
  while (statement.step()) {
    const auto found = row_of_case.find(statement.integer(0));
    if (found != row_of_case.end()) table.cases[found->second].reentrained_sizes.push_back(statement.integer(1));
  }
}

CaseOutcome outcome_from(const SqliteStatement& row, std::size_t grid_point) {
  CaseOutcome c;
  c.grid_point = grid_point;
  c.outcome = parse_outcome(row.text(6)).value_or(ImpactOutcome::undetermined);
  c.restitution = row.optional_real(7);
  c.retained_mass_fraction = row.optional_real(8);
  c.damage_ratio = row.optional_real(9);
  c.energy_per_contact = row.optional_real(10);
  c.small_strain_exceeded = row.optional_integer(11).value_or(0) != 0;
  return c;
}

// Everything the statistics read of one result, as text: the result-set hash covers each of them,
// so that a result changed in any fitted number (not only its class) is refitted.
std::string case_identity(const std::string& result_key, const CaseOutcome& c) {
  std::string text = result_key + ":" + std::string(to_string(c.outcome));
  const auto add = [&text](const std::optional<double>& value) {
    char number[32] = "-";
    if (value) std::snprintf(number, sizeof number, "%.17g", *value);
    text += std::string(":") + number;
  };
  add(c.restitution);
  add(c.retained_mass_fraction);
  add(c.damage_ratio);
  add(c.energy_per_contact);
  text += c.small_strain_exceeded ? ":flagged:" : ":within:";
  for (const auto size : c.reentrained_sizes) text += std::to_string(size) + ",";
  return text + "\n";
}

}  // namespace

StudyOutcomes Store::study_outcomes(std::int64_t study_id) {
  auto db = read();
  StudyOutcomes outcomes;
  db->execute("BEGIN");
  try {
    outcomes.result_set_version = version_of(*db, study_id);
    auto statement = db->prepare(
        "SELECT sc.grid_key, sc.grid_point, r.case_id, c.hash, r.attempt, r.committed_at, r.outcome, r.restitution, "
        "r.retained_mass_fraction, r.damage_ratio, r.energy_per_contact, r.small_strain_exceeded "
        "FROM study_cases sc JOIN results r ON r.case_id = sc.case_id JOIN cases c ON c.id = sc.case_id WHERE "
        "sc.study_id = ? ORDER BY sc.position");
    statement.bind_all(study_id);
    std::map<std::string, std::size_t> point_of_key;
    std::unordered_map<std::int64_t, std::size_t> row_of_case;
    std::vector<std::string> result_keys;
    while (statement.step()) {
      const auto [point, inserted] = point_of_key.emplace(statement.text(0), outcomes.table.grid_points.size());
      if (inserted) outcomes.table.grid_points.push_back(nlohmann::ordered_json::parse(statement.text(1)));
      row_of_case[statement.integer(2)] = outcomes.table.cases.size();
      outcomes.table.cases.push_back(outcome_from(statement, point->second));
      result_keys.push_back(statement.text(3) + ":" + std::to_string(statement.integer(4)) + ":" +
                            std::to_string(statement.real(5)));
    }
    add_reentrained_fragments(*db, study_id, row_of_case, outcomes.table);
    for (std::size_t i = 0; i < result_keys.size(); ++i)
      outcomes.identity += case_identity(result_keys[i], outcomes.table.cases[i]);
    db->execute("COMMIT");
  } catch (...) {
    db->execute("ROLLBACK");
    throw;
  }
  if (!outcomes.table.grid_points.empty())
    for (const auto& [axis, value] : outcomes.table.grid_points.front().items()) outcomes.table.axes.push_back(axis);
  return outcomes;
}

std::optional<StoredCorrelations> Store::stored_correlations(std::int64_t study_id, const std::string& request_key) {
  auto db = read();
  auto statement = db->prepare(
      "SELECT id, result_set_version, result_set_hash, aerobreak_version, computed_at, fit_seconds, summary "
      "FROM correlation_sets WHERE study_id = ? AND request = ?");
  statement.bind_all(study_id, request_key);
  if (!statement.step()) return std::nullopt;
  return StoredCorrelations{statement.integer(0), statement.integer(1), statement.text(2), statement.text(3),
                            statement.real(4),    statement.real(5),    statement.text(6)};
}

std::optional<std::string> Store::stored_fit(std::int64_t set_id, const std::string& name) {
  auto db = read();
  auto statement = db->prepare("SELECT document FROM correlation_fits WHERE set_id = ? AND name = ?");
  statement.bind_all(set_id, name);
  if (!statement.step()) return std::nullopt;
  return statement.text(0);
}

std::vector<std::string> Store::stored_fit_names(std::int64_t set_id) {
  auto db = read();
  auto statement = db->prepare("SELECT name FROM correlation_fits WHERE set_id = ? ORDER BY name");
  statement.bind_all(set_id);
  std::vector<std::string> names;
  while (statement.step()) names.push_back(statement.text(0));
  return names;
}

void Store::save_correlations(std::int64_t study_id, const std::string& request_key, const StoredCorrelations& set,
                              const std::vector<StoredFit>& fits) {
  std::lock_guard lock(write_mutex_);
  SqliteTransaction transaction(*writer_);
  writer_->prepare("DELETE FROM correlation_sets WHERE study_id = ? AND request = ?")
      .bind_all(study_id, request_key)
      .run();
  writer_
      ->prepare(
          "INSERT INTO correlation_sets (study_id, request, result_set_version, result_set_hash, aerobreak_version, "
          "computed_at, fit_seconds, summary) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
      .bind_all(study_id, request_key, set.result_set_version, set.result_set_hash, set.aerobreak_version,
                set.computed_at, set.fit_seconds, set.summary)
      .run();
  const std::int64_t set_id = writer_->last_insert_id();
  auto insert =
      writer_->prepare("INSERT INTO correlation_fits (set_id, name, kind, status, document) VALUES (?, ?, ?, ?, ?)");
  for (const StoredFit& fit : fits) {
    insert.reset();
    insert.bind_all(set_id, fit.name, fit.kind, fit.status, fit.document).run();
  }
  transaction.commit();
}

bool Store::confirm_correlations(std::int64_t study_id, const std::string& request_key,
                                 const std::string& result_set_hash, std::int64_t version) {
  std::lock_guard lock(write_mutex_);
  writer_
      ->prepare(
          "UPDATE correlation_sets SET result_set_version = ? WHERE study_id = ? AND request = ? AND result_set_hash = "
          "?")
      .bind_all(version, study_id, request_key, result_set_hash)
      .run();
  return writer_->changes() == 1;
}

}  // namespace aerobreak
