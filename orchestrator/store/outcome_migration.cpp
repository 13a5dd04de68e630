#include "orchestrator/store/outcome_migration.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/impact/outcome.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

// Results are read and rewritten this many at a time, so that a large store needs little memory.
constexpr int kBatch = 256;

const Json& at(const Json& document, const char* pointer) {
  static const Json null;
  const Json::json_pointer path(pointer);
  return document.contains(path) ? document[path] : null;
}

// A stored fragment's velocity as the outcome rule reads it: the window mean of the document's
// fragment list where it has one, else its last velocity; nothing (zero speed, the table's
// normal velocity) when the document does not list the fragment.
void read_velocity(const Json& listed, const Json& wall_normal, FragmentFate& fate) {
  const Json& velocity =
      listed.value("mean_velocity", Json()).is_array() ? listed["mean_velocity"] : listed.value("velocity", Json());
  if (!velocity.is_array() || velocity.size() != 3 || !wall_normal.is_array() || wall_normal.size() != 3) return;
  double normal = 0.0, speed2 = 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    const double v = velocity[a].is_number() ? velocity[a].get<double>() : 0.0;
    normal += v * (wall_normal[a].is_number() ? wall_normal[a].get<double>() : 0.0);
    speed2 += v * v;
  }
  fate.normal_velocity = normal;
  fate.speed = std::sqrt(speed2);
}

std::vector<FragmentFate> stored_fates(SqliteDatabase& db, std::int64_t case_id, const Json& document) {
  const Json& list = at(document, "/fragments/list");
  const Json& wall_normal = at(document, "/setup/wall_normal");
  auto rows = db.prepare(
      "SELECT rank, primaries, mass, on_wall, normal_velocity FROM fragments WHERE case_id = ? ORDER BY rank");
  rows.bind_all(case_id);
  std::vector<FragmentFate> fates;
  while (rows.step()) {
    FragmentFate fate;
    const auto rank = static_cast<std::size_t>(rows.integer(0));
    fate.primaries = static_cast<std::size_t>(rows.integer(1));
    fate.mass = rows.real(2);
    fate.on_wall = rows.integer(3) != 0;
    fate.normal_velocity = rows.optional_real(4).value_or(0.0);
    fate.speed = std::abs(fate.normal_velocity);
    if (list.is_array() && rank < list.size() && list[rank].is_object()) read_velocity(list[rank], wall_normal, fate);
    fates.push_back(fate);
  }
  return fates;
}

// The bounce share the case asked for, if the rule accepts it (format-1 cases allowed any share
// in (0, 1]); else the default.
OutcomeThresholds stored_thresholds(const Json& document) {
  OutcomeThresholds thresholds;
  const Json& share = at(document, "/case/classification/largest_fragment_share");
  if (share.is_number() && share.get<double>() > 0.5 && share.get<double>() <= 1.0)
    thresholds.bounce_share = share.get<double>();
  return thresholds;
}

void rewrite_outcome(Json& outcome, const Classification& c, const std::vector<FragmentFate>& fates,
                     const OutcomeThresholds& thresholds) {
  const Json former = outcome.value("class", Json());
  Json reentrained = Json::array();
  for (const std::size_t k : c.reentrained)
    reentrained.push_back({{"primaries", fates[k].primaries},
                           {"mass", fates[k].mass},
                           {"normal_velocity", fates[k].normal_velocity},
                           {"speed", fates[k].speed}});
  outcome.erase("mass_fraction_on_wall");
  outcome["class"] = to_string(c.outcome);
  outcome["reason"] = c.reason;
  outcome["fractured_on_wall"] = c.fractured_on_wall;
  outcome["retained_mass_fraction"] = c.retained_mass_fraction;
  outcome["reentrained_mass_fraction"] = c.reentrained_mass_fraction;
  outcome["reentrained_fragments"] = reentrained;
  outcome["damage_ratio"] = nullptr;
  outcome["largest_reentrained_share"] = c.largest_reentrained_share;
  outcome["thresholds"]["largest_fragment_share"] = thresholds.bounce_share;
  outcome["reclassified_from"] = former;
}

void reclassify(SqliteDatabase& db, std::int64_t case_id, Json document) {
  const std::vector<FragmentFate> fates = stored_fates(db, case_id, document);
  if (fates.empty() || !document.is_object()) return;
  const Json& settled = at(document, "/run/settled");
  const bool was_settled =
      settled.is_boolean() ? settled.get<bool>() : at(document, "/outcome/class") != Json("undetermined");
  const OutcomeThresholds thresholds = stored_thresholds(document);
  const Classification c = classify(fates, was_settled, thresholds);
  rewrite_outcome(document["outcome"], c, fates, thresholds);
  const Json& initial = at(document, "/contacts/initial");
  db.prepare(
        "UPDATE results SET outcome = ?, retained_mass_fraction = ?, reentrained_mass_fraction = ?, "
        "fractured_on_wall = ?, initial_contacts = ?, document = ? WHERE case_id = ?")
      .bind_all(to_string(c.outcome), c.retained_mass_fraction, c.reentrained_mass_fraction,
                c.fractured_on_wall ? 1 : 0,
                initial.is_number_integer() ? std::optional(initial.get<std::int64_t>()) : std::nullopt,
                document.dump(), case_id)
      .run();
}

}  // namespace

void reclassify_stored_results(SqliteDatabase& db) {
  std::int64_t after = -1;
  for (;;) {
    std::vector<std::pair<std::int64_t, std::string>> batch;
    auto rows = db.prepare("SELECT case_id, document FROM results WHERE case_id > ? ORDER BY case_id LIMIT ?");
    rows.bind_all(after, kBatch);
    while (rows.step()) batch.emplace_back(rows.integer(0), rows.text(1));
    if (batch.empty()) return;
    for (const auto& [case_id, text] : batch) {
      Json document = Json::parse(text, nullptr, false);
      if (!document.is_discarded()) reclassify(db, case_id, std::move(document));
      after = case_id;
    }
  }
}

}  // namespace aerobreak
