#pragma once
// A study in a real store file for the export tests: speeds 0.01, 0.02, 0.05 d/tau x gamma/k_n
// 0.001, 0.01 x N = 8, 32, four replicates, with results written through the store's own commit
// (as a worker's would be). Each replicate's fragments are chosen so that every class occurs and
// every number of the tables can be computed by hand from `fragments_of`; and a study of the same
// grid on two walls (fill_wall_study: a boolean axis /wall/adhesive).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "orchestrator/store/store.hpp"

namespace aerobreak::testing {

struct Fragment {
  int size;
  bool on_wall;
};

inline const std::vector<double> kSpeeds{0.01, 0.02, 0.05};
inline const std::vector<double> kGammas{0.001, 0.01};
inline const std::vector<int> kSizes{8, 32};
inline constexpr int kReplicates = 4;

// Replicate r at speed index s: s = 0 sticks whole; s = 1 loses r monomers (r = 0: stick);
// s = 2 breaks: a dimer and two monomers leave, r = 3 bounces (everything but one monomer leaves).
inline std::vector<Fragment> fragments_of(int size, std::size_t speed_index, int replicate) {
  if (speed_index == 0) return {{size, true}};
  if (speed_index == 1) {
    std::vector<Fragment> fragments{{size - replicate, true}};
    for (int i = 0; i < replicate; ++i) fragments.push_back({1, false});
    return fragments;
  }
  if (replicate == 3) return {{size - 1, false}, {1, true}};
  return {{size - 4, true}, {2, false}, {1, false}, {1, false}};
}

inline std::string outcome_of(const std::vector<Fragment>& fragments, int size) {
  double off = 0.0, largest_off = 0.0;
  for (const auto& f : fragments)
    if (!f.on_wall) off += f.size, largest_off = std::max(largest_off, static_cast<double>(f.size));
  if (off == 0.0) return "stick";
  return largest_off >= 0.9 * size ? "bounce" : "break-up";
}

inline nlohmann::ordered_json result_of(const std::vector<Fragment>& fragments, int size) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  double retained = 0.0;
  for (const auto& f : fragments) {
    list.push_back(
        {{"size", f.size}, {"mass", static_cast<double>(f.size)}, {"on_wall", f.on_wall}, {"normal_velocity", 0.001}});
    if (f.on_wall) retained += f.size;
  }
  retained /= size;
  return {{"dimensionless", {{"initial_contacts", size - 1}, {"energy_per_contact", 1.0}}},
          {"outcome",
           {{"class", outcome_of(fragments, size)},
            {"fractured_on_wall", false},
            {"retained_mass_fraction", retained},
            {"reentrained_mass_fraction", 1.0 - retained},
            {"damage_ratio", 1.0 - retained},
            {"largest_fragment_share", 1.0},
            {"fragment_count", fragments.size()},
            // the largest fragment's restitution: of a bounce, and of a stick or break-up (negative on
            // the wall), which the tables must not average in
            {"restitution", {{"normal", outcome_of(fragments, size) == "bounce" ? 0.2 : -0.3}}}}},
          {"validity", {{"small_strain", true}}},
          {"fragments", {{"list", list}}}};
}

// Replicate r of a grid point: a reduced-units case of N = size ballistic primaries (seed r).
inline StudySubmission::Case reduced_case(nlohmann::ordered_json grid_point, double speed, double gamma, int size,
                                          int r) {
  StudySubmission::Case c;
  c.grid_point = std::move(grid_point);
  c.grid_key = c.grid_point.dump();
  c.replicate = r;
  c.hash = c.grid_key + "/" + std::to_string(r);
  c.document = {{"units", "reduced"},
                {"cluster", {{"generator", {{"method", "ballistic"}, {"primaries", size}, {"seed", r}}}}},
                {"material", {{"gamma_over_kn", gamma}, {"poisson_ratio", 0.3}}},
                {"impact", {{"speed", speed}, {"angle", 0}}}};
  return c;
}

// A study without cases yet: its name and a content hash of one repeated character.
inline StudySubmission named_study(const std::string& name, char hash) {
  StudySubmission study;
  study.hash = std::string(64, hash);
  study.name = name;
  study.document = {{"name", study.name}};
  return study;
}

inline StudySubmission export_submission() {
  auto study = named_study("export", 'e');
  for (const double speed : kSpeeds)
    for (const double gamma : kGammas)
      for (const int size : kSizes)
        for (int r = 0; r < kReplicates; ++r)
          study.cases.push_back(reduced_case({{"impact_speed", speed}, {"gamma_over_kn", gamma}, {"primaries", size}},
                                             speed, gamma, size, r));
  return study;
}

// What decides the fragments of a case: its size, speed index in kSpeeds and replicate (its seed).
struct CaseLabel {
  int size;
  std::size_t speed_index;
  int replicate;
};

inline CaseLabel case_label(const nlohmann::ordered_json& document) {
  const double speed = document.at("impact").at("speed");
  return {document.at("cluster").at("generator").at("primaries").get<int>(),
          static_cast<std::size_t>(std::find(kSpeeds.begin(), kSpeeds.end(), speed) - kSpeeds.begin()),
          document.at("cluster").at("generator").at("seed").get<int>()};
}

// Submits the study and commits every case's result, fragments_for(case document); returns the study's id.
template <typename FragmentsFor>
std::int64_t fill_study(Store& store, const StudySubmission& submission, const FragmentsFor& fragments_for) {
  const auto receipt = store.submit_study(submission);
  const auto job = store.start_job("export test", 1);
  while (const auto claimed = store.claim_next_case(job)) {
    const int size = case_label(claimed->document).size;
    REQUIRE(store.commit_result(claimed->case_id, claimed->attempt, result_of(fragments_for(claimed->document), size),
                                "", 0.1));
  }
  return receipt.study_id;
}

inline std::int64_t fill_export_study(Store& store) {
  return fill_study(store, export_submission(), [](const nlohmann::ordered_json& document) {
    const auto label = case_label(document);
    return fragments_of(label.size, label.speed_index, label.replicate);
  });
}

// The same speeds, sizes and replicates at gamma/k_n 0.001 on two walls (axis /wall/adhesive):
// the adhesive wall leaves fragments_of; the wall without adhesion makes every cluster leave:
// whole (a bounce) below the fastest speed, and at it in two halves (break-up) for even replicates,
// whole for odd ones. Rows of the two walls differ in every output.
inline std::vector<Fragment> wall_fragments_of(bool adhesive, int size, std::size_t speed_index, int replicate) {
  if (adhesive) return fragments_of(size, speed_index, replicate);
  if (speed_index < 2 || replicate % 2 == 1) return {{size, false}};
  return {{size / 2, false}, {size / 2, false}};
}

inline std::int64_t fill_wall_study(Store& store) {
  auto study = named_study("walls", 'w');
  study.document["axes"] = {{"impact_speed", {{"values", kSpeeds}}},
                            {"primaries", {{"values", kSizes}}},
                            {"/wall/adhesive", {{"values", {true, false}}}}};
  for (const double speed : kSpeeds)
    for (const int size : kSizes)
      for (const bool adhesive : {true, false})
        for (int r = 0; r < kReplicates; ++r) {
          auto c = reduced_case({{"impact_speed", speed}, {"primaries", size}, {"/wall/adhesive", adhesive}}, speed,
                                0.001, size, r);
          c.document["wall"] = {{"adhesive", adhesive}};
          study.cases.push_back(std::move(c));
        }
  return fill_study(store, study, [](const nlohmann::ordered_json& document) {
    const auto label = case_label(document);
    return wall_fragments_of(document.at("wall").at("adhesive").get<bool>(), label.size, label.speed_index,
                             label.replicate);
  });
}

}  // namespace aerobreak::testing
