#pragma once
// Shared set-up of the store tests: a fresh store file per test, and submissions and result
// documents small enough to read at a glance.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "orchestrator/store/store.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {

// A store file in a fresh temporary directory, removed with the object.
class TemporaryStoreFile {
 public:
  explicit TemporaryStoreFile(const std::string& name) : directory_("store_" + name) {}
  std::filesystem::path path() const { return directory_.path() / "store.sqlite"; }

 private:
  ScratchDirectory directory_;
};

// A study of `speeds` x `replicates` cases whose hashes are made from the study tag, so that two
// studies with the same tag share their cases.
inline StudySubmission submission(const std::string& study_hash, const std::string& case_tag,
                                  std::initializer_list<double> speeds, int replicates = 1, int max_attempts = 3) {
  StudySubmission study;
  study.hash = study_hash;
  study.name = "study " + study_hash;
  study.document = {{"name", study.name}};
  study.max_attempts = max_attempts;
  study.case_wall_time = 60.0;
  for (const double speed : speeds) {
    for (int replicate = 0; replicate < replicates; ++replicate) {
      StudySubmission::Case study_case;
      study_case.grid_point = {{"impact_speed", speed}};
      study_case.grid_key = study_case.grid_point.dump();
      study_case.replicate = replicate;
      study_case.hash = case_tag + "/" + study_case.grid_key + "/" + std::to_string(replicate);
      study_case.document = {{"impact", {{"speed", speed}}}, {"replicate", replicate}};
      study.cases.push_back(std::move(study_case));
    }
  }
  return study;
}

// What a result document says beyond its class and fragments (schemas/result.schema.json).
struct ResultSummary {
  double retained = 1.0;
  bool fractured_on_wall = false;
  bool small_strain = true;
  double damage_ratio = 0.25;
  double energy_per_contact = 2.0;
};

inline nlohmann::ordered_json result_document(const std::string& outcome, std::initializer_list<int> fragment_sizes,
                                              const ResultSummary& summary = {}) {
  nlohmann::ordered_json fragments = nlohmann::ordered_json::array();
  int largest = 0;
  int total = 0;
  for (const int size : fragment_sizes) {
    fragments.push_back({{"size", size},
                         {"mass", static_cast<double>(size)},
                         {"on_wall", true},
                         {"normal_velocity", -0.001},
                         {"radius_of_gyration", 1.5}});
    largest = std::max(largest, size);
    total += size;
  }
  return {{"dimensionless",
           {{"initial_contacts", total - 1},
            {"energy_per_contact", summary.energy_per_contact},
            {"energy_over_rolling", nullptr}}},
          {"outcome",
           {{"class", outcome},
            {"fractured_on_wall", summary.fractured_on_wall},
            {"retained_mass_fraction", summary.retained},
            {"reentrained_mass_fraction", 1.0 - summary.retained},
            {"damage_ratio", summary.damage_ratio},
            {"largest_fragment_share", static_cast<double>(largest) / total},
            {"fragment_count", fragments.size()},
            {"restitution", {{"normal", 0.25}, {"tangential", nullptr}}}}},
          {"validity", {{"small_strain", summary.small_strain}}},
          {"setup", {{"impact_kinetic_energy", 0.002}}},
          {"fragments", {{"list", fragments}}}};
}

}  // namespace aerobreak::testing
