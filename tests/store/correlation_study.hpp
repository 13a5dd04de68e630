#pragma once
// A finished study in a real store, for the correlation tests of the store and the service: eight
// speeds x two cluster sizes x `replicates`, outcomes drawn (seeded) from a logistic law in log
// speed with v50 = 0.05 (N = 32) and 0.06 (N = 128), each result committed through the store.
#include <cmath>
#include <random>

#include "orchestrator/store/store.hpp"

namespace aerobreak::testing {

inline StudySubmission correlation_study_submission(const std::string& hash, int replicates) {
  const std::vector<double> speeds{0.01, 0.02, 0.03, 0.05, 0.08, 0.12, 0.2, 0.3};
  StudySubmission study;
  study.hash = hash;
  study.name = "correlations " + hash;
  study.document = {{"name", study.name},
                    {"base", {{"cluster", {{"generator", {{"method", "ballistic"}}}}}}},
                    {"axes", {{"impact_speed", {{"values", speeds}}}, {"primaries", {{"values", {32, 128}}}}}}};
  study.case_wall_time = 60.0;
  for (const double speed : speeds)
    for (const int primaries : {32, 128})
      for (int replicate = 0; replicate < replicates; ++replicate) {
        StudySubmission::Case c;
        c.grid_point = {{"impact_speed", speed}, {"primaries", primaries}};
        c.grid_key = c.grid_point.dump();
        c.replicate = replicate;
        c.hash = hash + "/" + c.grid_key + "/" + std::to_string(replicate);
        c.document = {{"cluster", {{"generator", {{"method", "ballistic"}, {"primaries", primaries}}}}},
                      {"impact", {{"speed", speed}}},
                      {"replicate", replicate}};
        study.cases.push_back(std::move(c));
      }
  return study;
}

// A result document of the shared outcome interface (schemas/result.schema.json): break-up leaves
// four fragments of sizes 1 and 3 off the wall, bounce one fragment of N; the energy per contact
// grows as the speed squared (5 at 0.05, with a +-10 % spread between replicates), and results from
// 0.2 on are flagged outside the small-strain range.
inline nlohmann::ordered_json correlation_result(const std::string& outcome, int primaries, double retained,
                                                 double speed, double spread) {
  nlohmann::ordered_json fragments = nlohmann::ordered_json::array();
  const auto fragment = [&fragments](int size, bool on_wall) {
    fragments.push_back({{"size", size},
                         {"mass", double(size)},
                         {"on_wall", on_wall},
                         {"normal_velocity", 0.01},
                         {"radius_of_gyration", 1.0}});
  };
  if (outcome == "bounce")
    fragment(primaries, false);
  else
    fragment(static_cast<int>(std::lround(retained * primaries)), true);
  if (outcome == "break-up")
    for (int k = 0; k < 4; ++k) fragment(k % 2 ? 3 : 1, false);
  return {{"outcome",
           {{"class", outcome},
            {"fractured_on_wall", false},
            {"fragment_count", fragments.size()},
            {"restitution", {{"normal", outcome == "bounce" ? 0.3 : 0.0}, {"tangential", nullptr}}},
            {"retained_mass_fraction", retained},
            {"reentrained_mass_fraction", 1.0 - retained},
            {"damage_ratio", outcome == "stick" ? 0.02 : 0.2}}},
          {"validity", {{"small_strain", speed < 0.2}}},
          {"dimensionless",
           {{"energy_per_contact", 5.0 * std::pow(speed / 0.05, 2.0) * (1.0 + spread)},
            {"initial_contacts", primaries - 1}}},
          {"setup", {{"impact_kinetic_energy", 0.002}}},
          {"fragments", {{"list", fragments}}}};
}

// Submits the study and commits a result for every case; returns the study id.
inline std::int64_t finished_correlation_study(Store& store, const std::string& hash, int replicates,
                                               std::uint64_t seed) {
  const auto receipt = store.submit_study(correlation_study_submission(hash, replicates));
  std::mt19937_64 engine(seed);
  const auto job = store.start_job("test", 1);
  while (const auto claimed = store.claim_next_case(job)) {
    const double speed = claimed->document["impact"]["speed"].get<double>();
    const int primaries = claimed->hash.find("\"primaries\":128") != std::string::npos ? 128 : 32;
    const double v50 = primaries == 32 ? 0.05 : 0.06;
    const double p = 1.0 / (1.0 + std::pow(speed / v50, -3.0));
    const double u = static_cast<double>(engine() >> 11) * 0x1.0p-53;
    const std::string outcome = u < p ? "break-up" : (u < p + 0.05 ? "bounce" : "stick");
    const double retained = outcome == "stick" ? 1.0 : outcome == "bounce" ? 0.0 : 1.0 - p * 0.8;
    const double spread = 0.2 * (static_cast<double>(engine() >> 11) * 0x1.0p-53 - 0.5);
    store.commit_result(claimed->case_id, claimed->attempt,
                        correlation_result(outcome, primaries, retained, speed, spread), "", 0.1);
  }
  store.end_job(job, 0, "done");
  return receipt.study_id;
}

}  // namespace aerobreak::testing
