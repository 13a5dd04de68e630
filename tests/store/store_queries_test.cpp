// The reader side: progress, paging and filtering, outcome counts per grid point.
#include "tests/store/store_support.hpp"

namespace aerobreak {

TEST_CASE("Progress counts cases by status and estimates the time left from the rate", "[store]") {
  testing::TemporaryStoreFile file("progress");
  Store store(file.path());
  const auto study = store.submit_study(testing::submission("s1", "c", {0.1, 0.2, 0.3, 0.4}));
  const auto job = store.start_job("test", 1);
  const auto a = store.claim_next_case(job);
  CHECK(store.commit_result(a->case_id, a->attempt, testing::result_document("stick", {2}), "", 1.0));
  store.claim_next_case(job);
  const auto progress = store.progress(study.study_id);
  REQUIRE(progress);
  CHECK(progress->total == 4);
  CHECK(progress->by_status.at("done") == 1);
  CHECK(progress->by_status.at("running") == 1);
  CHECK(progress->by_status.at("queued") == 2);
  CHECK(progress->by_status.at("failed") == 0);
  CHECK_FALSE(progress->complete);
  CHECK(progress->cases_per_hour > 0.0);
  REQUIRE(progress->seconds_left);
  CHECK(*progress->seconds_left == Approx(3.0 * 3600.0 / progress->cases_per_hour));
  CHECK_FALSE(store.progress(study.study_id + 1));
}

TEST_CASE("Cases and results are paged in submission order and filtered", "[store]") {
  testing::TemporaryStoreFile file("paging");
  Store store(file.path());
  const auto study = store.submit_study(testing::submission("s1", "c", {0.1, 0.2, 0.3, 0.4, 0.5}));
  const auto job = store.start_job("test", 1);
  const char* outcomes[] = {"stick", "bounce", "stick"};
  for (const char* outcome : outcomes) {
    const auto claimed = store.claim_next_case(job);
    REQUIRE(claimed);
    store.commit_result(claimed->case_id, claimed->attempt, testing::result_document(outcome, {4}), "", 1.0);
  }
  const auto page = store.cases(study.study_id, std::nullopt, {2, 1});
  CHECK(page.total == 5);
  REQUIRE(page.items.size() == 2);
  CHECK(page.items[0].grid_point.at("impact_speed") == 0.2);
  CHECK(page.items[0].outcome == "bounce");
  CHECK(store.cases(study.study_id, CaseStatus::queued, {}).total == 2);
  const auto sticks = store.results(study.study_id, std::string("stick"), {});
  CHECK(sticks.total == 2);
  CHECK(sticks.items[1].grid_point.at("impact_speed") == 0.3);
}

TEST_CASE("Outcome counts are grouped per grid point over the replicates", "[store]") {
  testing::TemporaryStoreFile file("outcomes");
  Store store(file.path());
  const auto study = store.submit_study(testing::submission("s1", "c", {0.1, 0.2}, 3));
  const auto job = store.start_job("test", 1);
  const char* outcomes[] = {"stick", "stick", "bounce", "break-up"};
  for (const char* outcome : outcomes) {
    const auto claimed = store.claim_next_case(job);
    store.commit_result(claimed->case_id, claimed->attempt, testing::result_document(outcome, {4}), "", 1.0);
  }
  const auto last = store.claim_next_case(job);
  store.record_failure(last->case_id, last->attempt, AttemptEnd::invalid, "bad");
  const auto cells = store.outcomes(study.study_id);
  REQUIRE(cells.size() == 2);
  CHECK(cells[0].grid_point.at("impact_speed") == 0.1);
  CHECK(cells[0].cases == 3);
  CHECK(cells[0].outcomes.at("stick") == 2);
  CHECK(cells[0].outcomes.at("bounce") == 1);
  CHECK(cells[0].finished() == 3);
  CHECK(cells[1].outcomes.at("break-up") == 1);
  CHECK(cells[1].failed == 1);
  CHECK(cells[1].finished() == 1);
}

TEST_CASE("Results and outcome tables carry the retained mass, the damage and the small-strain flags", "[store]") {
  testing::TemporaryStoreFile file("outcome-columns");
  Store store(file.path());
  const auto study = store.submit_study(testing::submission("s1", "c", {0.1, 0.2}, 3));
  const auto job = store.start_job("test", 1);
  const testing::ResultSummary summaries[] = {{1.0, false, true, 0.0, 1.0},
                                              {1.0, true, true, 0.2, 2.0},
                                              {0.4, true, false, 0.5, 3.0},  // speed 0.1
                                              {0.7, false, false, 0.4, 5.0},
                                              {0.1, false, false, 0.9, 7.0}};  // speed 0.2
  const char* outcomes[] = {"stick", "stick", "break-up", "break-up", "break-up"};
  for (std::size_t k = 0; k < 5; ++k) {
    const auto claimed = store.claim_next_case(job);
    REQUIRE(claimed);
    store.commit_result(claimed->case_id, claimed->attempt, testing::result_document(outcomes[k], {4}, summaries[k]),
                        "", 1.0);
  }
  const auto page = store.results(study.study_id, std::nullopt, {});
  REQUIRE(page.items.size() == 5);
  const ResultRecord& third = page.items[2];
  CHECK(third.retained_mass_fraction == Approx(0.4));
  CHECK(third.reentrained_mass_fraction == Approx(0.6));
  CHECK(third.damage_ratio == Approx(0.5));
  CHECK(third.fractured_on_wall == true);
  CHECK(third.small_strain_exceeded == true);
  CHECK(third.energy_per_contact == Approx(3.0));
  CHECK_FALSE(third.energy_over_rolling);
  CHECK(third.initial_contacts == 3);
  CHECK(page.items[0].small_strain_exceeded == false);

  const auto cells = store.grid_statistics(study.study_id);
  REQUIRE(cells.size() == 2);
  CHECK(mean_estimate(cells[0].retained_mass_fraction)->mean == Approx((1.0 + 1.0 + 0.4) / 3.0));
  // Squared deviations from the mean 0.8, summed in SQL by Welford's update: 0.2^2 + 0.2^2 + 0.4^2.
  CHECK(cells[0].retained_mass_fraction.squared_deviations == Approx(0.24).epsilon(1e-14));
  CHECK(mean_estimate(cells[0].damage_ratio)->mean == Approx((0.0 + 0.2 + 0.5) / 3.0));
  CHECK(mean_estimate(cells[0].energy_per_contact)->mean == Approx(2.0));
  CHECK(cells[0].outcomes.fractured_on_wall == 2);
  CHECK(cells[0].outcomes.small_strain_exceeded == 1);
  CHECK(cells[0].outcomes.small_strain_unchecked == 0);
  CHECK(mean_estimate(cells[1].retained_mass_fraction)->mean == Approx(0.4));
  CHECK(cells[1].retained_mass_fraction.count == 2);
  CHECK(cells[1].retained_mass_fraction.squared_deviations == Approx(0.3 * 0.3 * 2.0).epsilon(1e-14));  // 0.7, 0.1
  CHECK(cells[1].outcomes.small_strain_exceeded == 2);
  CHECK(cells[1].outcomes.finished() == 2);
}

}  // namespace aerobreak
