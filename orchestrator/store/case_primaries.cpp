#include "orchestrator/store/case_primaries.hpp"

#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/impact/case_inputs.hpp"

namespace aerobreak {

void fill_case_primaries(SqliteDatabase& db) {
  std::vector<std::pair<std::int64_t, std::int64_t>> found;  // (case id, N)
  auto cases = db.prepare("SELECT id, document FROM cases");
  while (cases.step()) {
    // A document that is not JSON (none is, but an old store is no place to fail) gives no N.
    const auto document = nlohmann::ordered_json::parse(cases.text(1), nullptr, false);
    if (const auto primaries = read_case_inputs(document).primaries) found.emplace_back(cases.integer(0), *primaries);
  }
  auto update = db.prepare("UPDATE cases SET primaries = ? WHERE id = ?");
  for (const auto& [id, primaries] : found) {
    update.reset();
    update.bind_all(primaries, id).run();
  }
}

}  // namespace aerobreak
