// The correlations' storage over a real SQLite file: the reader, the study's result-set version
// (Store::study_versions), the application layer's StudyFits that refits only when the result set
// changed, and its stored fits read back for the export.
#include <catch2/catch.hpp>

#include <tuple>

#include "orchestrator/app/study_fits.hpp"
#include "orchestrator/fitting/correlation_set.hpp"
#include "tests/store/correlation_study.hpp"
#include "tests/store/store_support.hpp"

namespace aerobreak::testing {
namespace {

// A store file named `file_name` holding one finished synthetic study (4 replicates, seed 2), the
// study's record, its default correlation request and the application layer's fits over the store.
struct FinishedStudy {
  FinishedStudy(const std::string& file_name, const std::string& hash)
      : file(file_name),
        store(file.path()),
        id(finished_correlation_study(store, hash, 4, 2)),
        study(*store.study(id)),
        request(correlation_request(study, std::nullopt)),
        fits(store) {}
  TemporaryStoreFile file;
  Store store;
  std::int64_t id;
  StudyRecord study;
  CorrelationRequest request;
  StudyFits fits;
};

}  // namespace

TEST_CASE("The store reads a study's outcomes with fragments, and counts changes of its result set",
          "[store][correlations]") {
  TemporaryStoreFile file("correlation_reader");
  Store store(file.path());
  const auto id = finished_correlation_study(store, "reader", 3, 1);
  const StudyOutcomes outcomes = store.study_outcomes(id);
  CHECK(outcomes.table.cases.size() == 48);
  CHECK(outcomes.table.grid_points.size() == 16);
  CHECK(outcomes.table.axes == std::vector<std::string>{"impact_speed", "primaries"});
  CHECK(outcomes.result_set_version == 48);  // one per committed result
  CHECK(store.study_versions(id)->result_set == 48);
  std::size_t break_ups = 0;
  for (const CaseOutcome& c : outcomes.table.cases) {
    REQUIRE(c.retained_mass_fraction);
    if (c.outcome == ImpactOutcome::break_up) {
      ++break_ups;
      CHECK(c.reentrained_sizes == std::vector<std::int64_t>{1, 3, 1, 3});
    }
    if (c.outcome == ImpactOutcome::stick) CHECK(c.reentrained_sizes.empty());
  }
  CHECK(break_ups > 0);
  // A second study naming the same cases gets its own count when it is linked to them.
  auto again = correlation_study_submission("reader", 3);
  again.hash = "reader-again";
  const auto second = store.submit_study(again).study_id;
  CHECK(store.study_versions(second)->result_set == 48);  // one per case linked with its result
  CHECK(store.study_versions(id)->result_set == 48);
}

TEST_CASE("Fits are stored, served while the result set is unchanged, refitted when it changes",
          "[store][correlations]") {
  FinishedStudy s("correlation_cache", "cache");
  const auto& [file, study, request, cache] = std::tie(s.file, s.study, s.request, s.fits);
  REQUIRE(request.covariates.size() == 1);
  CHECK(request.covariates[0].axis == "primaries");

  const StoredCorrelations first = *cache.current(study, request);
  CHECK(first.result_set_version == 64);
  CHECK(first.result_set_hash.size() == 64);
  const auto summary = nlohmann::json::parse(first.summary);
  CHECK(summary.at("provenance").at("result_set_hash") == first.result_set_hash);
  REQUIRE(s.store.stored_fit(first.set_id, "break-up.speed.g1"));
  CHECK_FALSE(s.store.stored_fit(first.set_id, "no-such-fit"));

  SECTION("unchanged: the same stored set") {
    const StoredCorrelations again = *cache.current(study, request);
    CHECK(again.set_id == first.set_id);
    CHECK(again.computed_at == first.computed_at);
  }
  SECTION("a version bump with the same results: confirmed, not refitted") {
    SqliteDatabase db(file.path());
    db.execute("UPDATE results SET outcome = outcome WHERE case_id = 1");
    const StoredCorrelations again = *cache.current(study, request);
    CHECK(again.result_set_version == 65);
    CHECK(again.computed_at == first.computed_at);
    CHECK(again.result_set_hash == first.result_set_hash);
  }
  SECTION("a changed result: refitted, with a new hash") {
    SqliteDatabase db(file.path());
    db.execute("UPDATE results SET outcome = 'undetermined' WHERE case_id = 1");
    const StoredCorrelations again = *cache.current(study, request);
    CHECK(again.result_set_version == 65);
    CHECK(again.result_set_hash != first.result_set_hash);
    CHECK(again.computed_at > first.computed_at);
  }
}

// Two different requests never share a stored or cached answer: the key covers the levels, the size
// and speed axes as well as the covariates (once it held the covariates only, and a request for
// other levels was answered with the default levels' fits).
TEST_CASE("The fits' cache keys on the whole request", "[store][correlations]") {
  FinishedStudy s("correlation_request_key", "keys");
  const auto& [store, study, request, cache] = std::tie(s.store, s.study, s.request, s.fits);
  CHECK(request.size_axis == "primaries");
  const auto first = cache.current(study, request);
  CorrelationRequest other_levels = request;
  other_levels.levels = {0.2, 0.5, 0.8};
  const auto second = cache.current(study, other_levels);
  CHECK(second->set_id != first->set_id);
  CHECK(nlohmann::json::parse(second->summary).at("request").at("levels") == nlohmann::json{0.2, 0.5, 0.8});
  const auto g1 = nlohmann::json::parse(*store.stored_fit(second->set_id, "break-up.speed.g1"));
  CHECK(g1.at("critical")[0].at("level") == 0.2);
  CHECK(cache.current(study, request)->set_id == first->set_id);  // each request keeps its own set
  for (const auto& change : {&CorrelationRequest::size_axis, &CorrelationRequest::speed_axis}) {
    CorrelationRequest changed = request;
    changed.*change = "another_axis";
    CHECK(request_key(changed) != request_key(request));
  }
}

// The lookup-table export evaluates the stored fits read back (StudyFits::logistic_fits), not a
// fresh fit of the study: read back they are the fits, number for number, and a stored document
// changed by hand is what the export then gets.
TEST_CASE("The export reads the study's stored fits back instead of fitting it again", "[store][correlations]") {
  FinishedStudy s("correlation_read_back", "read back");
  const auto& [file, store, study, fits] = std::tie(s.file, s.store, s.study, s.fits);
  const auto read = fits.logistic_fits(study);
  const CorrelationSet fresh = study_correlations(store, study, s.request);
  REQUIRE(read->logistic.size() == fresh.logistic.size());
  for (std::size_t i = 0; i < fresh.logistic.size(); ++i) {
    const auto &a = read->logistic[i], &b = fresh.logistic[i];
    INFO(b.common.name);
    CHECK(a.common.name == b.common.name);
    CHECK(a.common.status == b.common.status);
    CHECK(a.common.group == b.common.group);
    CHECK(a.common.coefficients == b.common.coefficients);  // bitwise: JSON keeps doubles exactly
    CHECK(a.common.covariance == b.common.covariance);
    REQUIRE(a.common.validity.size() == b.common.validity.size());
    for (std::size_t k = 0; k < a.common.validity.size(); ++k)
      CHECK(a.common.validity[k].max == b.common.validity[k].max);
    CHECK(a.covariates.size() == b.covariates.size());
    CHECK(a.data.successes.sum() == b.data.successes.sum());
    CHECK(a.critical.size() == b.critical.size());
  }
  CHECK(fits.logistic_fits(study) == read);  // kept per stored set
  SqliteDatabase db(file.path());
  db.execute(
      "UPDATE correlation_fits SET document = json_set(document, '$.parameters[0].estimate', 42.0) "
      "WHERE name = 'break-up.speed.g1'");
  StudyFits again(store);
  const auto changed = again.logistic_fits(study);
  for (const auto& fit : changed->logistic)
    if (fit.common.name == "break-up.speed.g1") CHECK(fit.common.coefficients[0] == 42.0);
}

TEST_CASE("Correlation requests that do not fit the study are refused with the reason", "[store][correlations]") {
  TemporaryStoreFile file("correlation_requests");
  Store store(file.path());
  const auto id = store.submit_study(correlation_study_submission("empty", 1)).study_id;
  const StudyRecord study = *store.study(id);
  CHECK_THROWS_WITH(correlation_request(study, std::vector<std::string>{"angle"}),
                    Catch::Contains("covariate 'angle' is not an axis of study") && Catch::Contains("impact_speed"));
  CHECK(correlation_request(study, std::vector<std::string>{"N"}).covariates.at(0).axis == "primaries");
  CHECK(correlation_request(study, std::vector<std::string>{}).covariates.empty());
  StudyFits cache(store);
  try {
    cache.current(study, correlation_request(study, std::nullopt));
    FAIL("a study without results was fitted");
  } catch (const CorrelationRequestError& error) {
    CHECK(error.no_results);
    CHECK(std::string(error.what()).find("has no results") != std::string::npos);
  }
}

TEST_CASE("Sets stored before the one shape of a mean are dropped by migration 11 and fitted again",
          "[store][correlations]") {
  std::string grid_points_before, fit_before;
  std::int64_t id = 0;
  TemporaryStoreFile file("correlation_migration_10");
  {
    Store store(file.path());
    id = finished_correlation_study(store, "migration-10", 4, 2);
    StudyFits fits(store);
    const auto study = *store.study(id);
    const auto stored = *fits.current(study, correlation_request(study, std::nullopt));
    grid_points_before = *store.stored_fit(stored.set_id, "grid-points");
    fit_before = *store.stored_fit(stored.set_id, "break-up.speed.g1");
  }
  {
    // The store as schema version 10 left it: the set stored, the version one lower.
    SqliteDatabase db(file.path());
    db.execute("PRAGMA user_version = 10");
  }
  Store store(file.path());
  CHECK(store.opened_at_version() == 10);
  const auto study = *store.study(id);
  const auto request = correlation_request(study, std::nullopt);
  CHECK_FALSE(store.stored_correlations(id, request_key(request)));
  StudyFits fits(store);
  const auto refitted = *fits.current(study, request);
  // The same documents, fitted again from the same results (the test's set had the new shape
  // already), but for the result-set version, which the migration's rebuild of the summaries raised.
  const auto without_version = [](const std::string& text) {
    auto document = nlohmann::json::parse(text);
    document.at("provenance").erase("result_set_version");
    return document;
  };
  CHECK(without_version(*store.stored_fit(refitted.set_id, "grid-points")) == without_version(grid_points_before));
  CHECK(without_version(*store.stored_fit(refitted.set_id, "break-up.speed.g1")) == without_version(fit_before));
}

}  // namespace aerobreak::testing
