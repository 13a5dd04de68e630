#include "orchestrator/store/migrations.hpp"

#include <array>
#include <string>

#include "orchestrator/store/case_primaries.hpp"
#include "orchestrator/store/outcome_migration.hpp"
#include "orchestrator/store/store_summaries.hpp"

namespace aerobreak {
namespace {

// Times are Unix seconds (REAL). Status columns are checked by the database itself, so that no
// writer bug can store a state the scheduler does not know.
constexpr std::string_view kVersion1 = R"sql(
CREATE TABLE studies (
  id             INTEGER PRIMARY KEY,
  hash           TEXT NOT NULL UNIQUE,
  name           TEXT NOT NULL,
  description    TEXT NOT NULL DEFAULT '',
  document       TEXT NOT NULL,
  status         TEXT NOT NULL CHECK (status IN ('active', 'cancelled')),
  max_attempts   INTEGER NOT NULL CHECK (max_attempts >= 1),
  case_wall_time REAL NOT NULL CHECK (case_wall_time > 0),
  created_at     REAL NOT NULL,
  cancelled_at   REAL
);

CREATE TABLE jobs (
  id          INTEGER PRIMARY KEY,
  command     TEXT NOT NULL,
  ranks       INTEGER NOT NULL,
  pid         INTEGER,
  hosts       TEXT,
  started_at  REAL NOT NULL,
  ended_at    REAL,
  exit_status INTEGER,
  note        TEXT
);

CREATE TABLE cases (
  id              INTEGER PRIMARY KEY,
  hash            TEXT NOT NULL UNIQUE,
  document        TEXT NOT NULL,
  status          TEXT NOT NULL CHECK (status IN ('queued', 'running', 'done', 'failed', 'cancelled')),
  attempts        INTEGER NOT NULL DEFAULT 0,
  failures        INTEGER NOT NULL DEFAULT 0,
  max_attempts    INTEGER NOT NULL CHECK (max_attempts >= 1),
  wall_time_limit REAL NOT NULL,
  job_id          INTEGER REFERENCES jobs (id),
  worker          TEXT,
  queued_at       REAL NOT NULL,
  started_at      REAL,
  finished_at     REAL,
  error           TEXT
);
CREATE INDEX cases_by_status ON cases (status, id);

CREATE TABLE study_cases (
  study_id   INTEGER NOT NULL REFERENCES studies (id),
  case_id    INTEGER NOT NULL REFERENCES cases (id),
  position   INTEGER NOT NULL,
  grid_point TEXT NOT NULL,
  grid_key   TEXT NOT NULL,
  replicate  INTEGER NOT NULL,
  PRIMARY KEY (study_id, case_id)
) WITHOUT ROWID;
CREATE INDEX study_cases_by_case ON study_cases (case_id);
CREATE INDEX study_cases_by_position ON study_cases (study_id, position);

CREATE TABLE attempts (
  case_id    INTEGER NOT NULL REFERENCES cases (id),
  attempt    INTEGER NOT NULL,
  job_id     INTEGER REFERENCES jobs (id),
  worker     TEXT,
  started_at REAL NOT NULL,
  ended_at   REAL,
  outcome    TEXT CHECK (outcome IN ('done', 'invalid', 'error', 'wall_time', 'lost', 'interrupted')),
  error      TEXT,
  PRIMARY KEY (case_id, attempt)
) WITHOUT ROWID;

CREATE TABLE results (
  case_id                INTEGER PRIMARY KEY REFERENCES cases (id),
  attempt                INTEGER NOT NULL,
  outcome                TEXT NOT NULL CHECK (outcome IN ('stick', 'bounce', 'break-up', 'undetermined')),
  restitution            REAL,
  largest_fragment_share REAL,
  fragment_count         INTEGER,
  mass_fraction_on_wall  REAL,
  impact_energy          REAL,
  wall_clock_seconds     REAL,
  data_file              TEXT,
  document               TEXT NOT NULL,
  committed_at           REAL NOT NULL
);

CREATE TABLE fragments (
  case_id            INTEGER NOT NULL REFERENCES results (case_id),
  rank               INTEGER NOT NULL,
  primaries          INTEGER NOT NULL,
  mass               REAL NOT NULL,
  on_wall            INTEGER NOT NULL,
  normal_velocity    REAL,
  radius_of_gyration REAL,
  PRIMARY KEY (case_id, rank)
) WITHOUT ROWID;
)sql";

// Outcomes decided by what leaves the wall (docs/IMPACT.md section 5): the fraction left on the
// wall is the retained one; the re-entrained fraction, whether the deposit is in pieces, the
// damage ratio, the small-strain flag and the energy groups come with every result. Stored
// results are classified again from their fragments (reclassify_stored_results).
constexpr std::string_view kVersion2 = R"sql(
ALTER TABLE results RENAME COLUMN mass_fraction_on_wall TO retained_mass_fraction;
ALTER TABLE results ADD COLUMN reentrained_mass_fraction REAL;
ALTER TABLE results ADD COLUMN damage_ratio REAL;
ALTER TABLE results ADD COLUMN fractured_on_wall INTEGER CHECK (fractured_on_wall IN (0, 1));
ALTER TABLE results ADD COLUMN small_strain_exceeded INTEGER CHECK (small_strain_exceeded IN (0, 1));
ALTER TABLE results ADD COLUMN energy_per_contact REAL;
ALTER TABLE results ADD COLUMN energy_over_rolling REAL;
ALTER TABLE results ADD COLUMN initial_contacts INTEGER;
)sql";

// Summaries of each study and of each of its grid points, kept by triggers (store_summaries.hpp):
// the read endpoints no longer aggregate every case of a study per request. migrate_store fills
// them and creates the triggers right after this step.
constexpr std::string_view kVersion3 = R"sql(
CREATE TABLE study_summaries (
  study_id           INTEGER PRIMARY KEY REFERENCES studies (id),
  queued             INTEGER NOT NULL DEFAULT 0,
  running            INTEGER NOT NULL DEFAULT 0,
  done               INTEGER NOT NULL DEFAULT 0,
  failed             INTEGER NOT NULL DEFAULT 0,
  cancelled          INTEGER NOT NULL DEFAULT 0,
  first_started_at   REAL,
  last_finished_at   REAL,
  finished_here      INTEGER NOT NULL DEFAULT 0,
  case_state_version INTEGER NOT NULL DEFAULT 0,
  result_set_version INTEGER NOT NULL DEFAULT 0
);

CREATE TABLE grid_point_summaries (
  study_id     INTEGER NOT NULL REFERENCES studies (id),
  grid_key     TEXT NOT NULL,
  position     INTEGER NOT NULL,
  grid_point   TEXT NOT NULL,
  cases        INTEGER NOT NULL DEFAULT 0,
  stick        INTEGER NOT NULL DEFAULT 0,
  bounce       INTEGER NOT NULL DEFAULT 0,
  break_up     INTEGER NOT NULL DEFAULT 0,
  undetermined INTEGER NOT NULL DEFAULT 0,
  failed       INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (study_id, grid_key)
) WITHOUT ROWID;
CREATE INDEX grid_point_summaries_by_position ON grid_point_summaries (study_id, position);
)sql";

// Each case's bulk file is checked against the size and SHA-256 its worker reported.
constexpr std::string_view kVersion4 = R"sql(
ALTER TABLE results ADD COLUMN data_file_size INTEGER;
ALTER TABLE results ADD COLUMN data_file_sha256 TEXT;
)sql";

// Correlations (docs/CORRELATIONS.md). correlation_sets holds one set of fits per study and request
// (the pooled models' covariates): its summary and, in correlation_fits, each fit's document;
// result_set_hash identifies the results it was fitted to, result_set_version the study's
// result-set version (study_summaries, migration 3) at which that hash was last found current.
constexpr std::string_view kVersion5 = R"sql(
CREATE TABLE correlation_sets (
  id                 INTEGER PRIMARY KEY,
  study_id           INTEGER NOT NULL REFERENCES studies (id),
  request            TEXT NOT NULL,
  result_set_version INTEGER NOT NULL,
  result_set_hash    TEXT NOT NULL,
  aerobreak_version  TEXT NOT NULL,
  computed_at        REAL NOT NULL,
  fit_seconds        REAL NOT NULL,
  summary            TEXT NOT NULL,
  UNIQUE (study_id, request)
);

CREATE TABLE correlation_fits (
  set_id   INTEGER NOT NULL REFERENCES correlation_sets (id) ON DELETE CASCADE,
  name     TEXT NOT NULL,
  kind     TEXT NOT NULL,
  status   TEXT NOT NULL,
  document TEXT NOT NULL,
  PRIMARY KEY (set_id, name)
) WITHOUT ROWID;
)sql";

// Indexes for the dashboard's per-grid-point reads (docs/PERFORMANCE.md, "Dashboard"): a study's
// cases by grid point (with study_cases' key, case_id), so that one grid point's cases are a range
// and the cases come grouped by grid point; and the results' summed columns beside their case id,
// so that aggregating them reads this index instead of the table, whose rows hold the result
// document (14 kB on average in real stores) with the outcome columns of version 2 after it.
constexpr std::string_view kVersion6 = R"sql(
CREATE INDEX study_cases_by_grid_key ON study_cases (study_id, grid_key);
CREATE INDEX results_statistics ON results (case_id, outcome, retained_mass_fraction, restitution, fragment_count,
  largest_fragment_share, damage_ratio, energy_per_contact, fractured_on_wall, small_strain_exceeded);
)sql";

// Adaptive boundary searches (docs/ADAPTIVE.md): each group of a search study with its state,
// current estimates and every round it placed; each case linked to its group and round.
constexpr std::string_view kVersion7 = R"sql(
ALTER TABLE study_cases ADD COLUMN search_group INTEGER;
ALTER TABLE study_cases ADD COLUMN search_round INTEGER;
CREATE INDEX study_cases_by_search_group ON study_cases (study_id, search_group) WHERE search_group IS NOT NULL;

CREATE TABLE search_groups (
  study_id    INTEGER NOT NULL REFERENCES studies (id),
  position    INTEGER NOT NULL,
  group_point TEXT NOT NULL,
  state       TEXT NOT NULL CHECK (state IN ('searching', 'converged', 'budget_spent', 'out_of_range', 'error')),
  rounds      INTEGER NOT NULL,
  cases       INTEGER NOT NULL,
  estimates   TEXT NOT NULL DEFAULT '[]',
  note        TEXT,
  updated_at  REAL NOT NULL,
  PRIMARY KEY (study_id, position)
) WITHOUT ROWID;

CREATE TABLE search_rounds (
  study_id   INTEGER NOT NULL,
  position   INTEGER NOT NULL,
  round      INTEGER NOT NULL,
  decided_at REAL NOT NULL,
  plan       TEXT NOT NULL,
  PRIMARY KEY (study_id, position, round),
  FOREIGN KEY (study_id, position) REFERENCES search_groups (study_id, position)
) WITHOUT ROWID;
)sql";

// Data-file paths relative to the data folder (data_paths.hpp), so that a store moved or copied
// with its data folder finds its files: every file the scheduler asked for is DATA/cases/HASH.h5,
// so a recorded absolute path that ends in /cases/HASH.h5 (HASH its case's) becomes cases/HASH.h5;
// any other path is kept as it is.
constexpr std::string_view kVersion8 = R"sql(
UPDATE results SET data_file = (SELECT 'cases/' || c.hash || '.h5' FROM cases c WHERE c.id = results.case_id)
WHERE data_file LIKE '/%'
  AND EXISTS (SELECT 1 FROM cases c
              WHERE c.id = results.case_id AND results.data_file LIKE '%/cases/' || c.hash || '.h5');
)sql";

// Each case's N, the primaries of its cluster, read from its document once, when the case is
// stored (fill_case_primaries for the cases already there): the statistics and the lookup tables
// read it from here. Null for a cluster file, whose N the document does not say.
constexpr std::string_view kVersion9 = R"sql(
ALTER TABLE cases ADD COLUMN primaries INTEGER CHECK (primaries >= 1);
)sql";

// The N of a cluster file's cases, which their documents do not say, from their results'
// fragments (every primary is in exactly one fragment), as a result now stores it when it comes;
// the correlation sets fitted while N was unknown are dropped, to be fitted again on request.
constexpr std::string_view kVersion10 = R"sql(
DELETE FROM correlation_sets WHERE study_id IN (
  SELECT DISTINCT sc.study_id FROM study_cases sc JOIN cases c ON c.id = sc.case_id
  WHERE c.primaries IS NULL AND EXISTS (SELECT 1 FROM fragments f WHERE f.case_id = c.id));
UPDATE cases SET primaries = (SELECT sum(f.primaries) FROM fragments f WHERE f.case_id = cases.id)
WHERE primaries IS NULL AND EXISTS (SELECT 1 FROM fragments f WHERE f.case_id = cases.id);
)sql";

// The stored correlation documents written before a mean had its one shape (the grid-points
// document's {n, mean, standard_error}, the retained-fraction fit's data rows) are dropped: the
// next request fits the study again from its results (fitting/mean_estimate.hpp,
// estimate_json.hpp), to the same fitted numbers, and stores the documents in the shape of
// schemas/correlation.schema.json.
constexpr std::string_view kVersion11 = R"sql(
DELETE FROM correlation_fits;
DELETE FROM correlation_sets;
)sql";

constexpr std::array kMigrations{
    Migration{1, "studies, cases, attempts, results, fragments, worker jobs", kVersion1},
    Migration{2, "outcomes by what leaves the wall: retained and re-entrained mass, damage, validity, energy groups",
              kVersion2, reclassify_stored_results},
    Migration{3, "per-study and per-grid-point summaries kept by triggers", kVersion3},
    Migration{4, "size and SHA-256 of each result's data file", kVersion4},
    Migration{5, "stored correlation sets and fits", kVersion5},
    Migration{6, "indexes for the dashboard: cases by grid point, the results' summed columns", kVersion6},
    Migration{7, "adaptive boundary searches: groups, rounds, cases linked to both", kVersion7},
    Migration{8, "data-file paths relative to the data folder", kVersion8},
    Migration{9, "each case's N (primaries of its cluster) beside its document", kVersion9, fill_case_primaries},
    Migration{10, "a cluster file's N from its results' fragments", kVersion10},
    Migration{11, "stored correlation sets dropped, to be fitted again with one shape of a mean", kVersion11},
};

int user_version(SqliteDatabase& db) {
  auto statement = db.prepare("PRAGMA user_version");
  statement.step();
  return static_cast<int>(statement.integer(0));
}

}  // namespace

std::span<const Migration> store_migrations() { return kMigrations; }

int latest_store_version() { return kMigrations.back().version; }

int migrate_store(SqliteDatabase& db) { return migrate_store(db, kMigrations); }

int migrate_store(SqliteDatabase& db, std::span<const Migration> steps) {
  const int found = user_version(db);
  const int latest = steps.empty() ? 0 : steps.back().version;
  if (found > latest) {
    throw SqliteError("the store has schema version " + std::to_string(found) + ", newer than this aerobreak (" +
                          std::to_string(latest) + "); use a newer aerobreak",
                      SQLITE_MISMATCH);
  }
  for (const Migration& step : steps) {
    if (step.version <= found) continue;
    SqliteTransaction transaction(db);
    // Whatever a step changes (outcomes re-classified, a table re-created), the summaries are
    // recomputed after it in the same transaction; their triggers stay out of its way meanwhile.
    drop_store_summary_triggers(db);
    db.execute(step.sql);
    if (step.upgrade) step.upgrade(db);
    if (has_store_summaries(db)) rebuild_store_summaries(db);
    db.execute("PRAGMA user_version = " + std::to_string(step.version));
    transaction.commit();
  }
  return found;
}

}  // namespace aerobreak
