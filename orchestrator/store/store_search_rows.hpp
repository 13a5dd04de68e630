#pragma once
#include <cstdint>
#include <vector>

#include "orchestrator/store/sqlite_database.hpp"
#include "orchestrator/store/store_types.hpp"

// Rows that a submission and a search round both write, inside the caller's transaction.
namespace aerobreak {

struct CaseSettings {
  int max_attempts = 3;
  double wall_time_limit = 3600.0;
  double now = 0.0;
};

// Stores each case once by its hash, with its N read from its document (engine/impact/case_inputs.hpp;
// a cancelled one is queued again), and links it to the study
// at positions first_position, first_position + 1, ...; counts what it did in `receipt`.
void link_study_cases(SqliteDatabase& db, std::int64_t study_id, const std::vector<StudySubmission::Case>& cases,
                      std::int64_t first_position, const CaseSettings& settings, SubmissionReceipt& receipt);

// A search's groups, each searching, with its round 0.
void insert_search_groups(SqliteDatabase& db, std::int64_t study_id,
                          const std::vector<StudySubmission::SearchGroup>& groups, double now);

}  // namespace aerobreak
