#include "orchestrator/app/study_submission.hpp"

#include <set>

namespace aerobreak {
namespace {

// A search's round 0: the cases of each group (`initial` of them, in group order) are linked to
// their group, and each group starts with the record of its first round.
void add_search_groups(const Study& study, StudySubmission& submission) {
  const auto per_group = static_cast<std::size_t>(study.search->initial);
  for (std::size_t k = 0; k < submission.cases.size(); ++k) {
    auto& c = submission.cases[k];
    const auto position = static_cast<std::int64_t>(k / per_group);
    c.search_group = position;
    c.search_round = 0;
    if (k % per_group == 0) {
      nlohmann::ordered_json group = c.grid_point;
      group.erase(study.search->axis);
      submission.search_groups.push_back({position,
                                          group,
                                          {{"round", 0},
                                           {"results", 0},
                                           {"estimates", nlohmann::ordered_json::array()},
                                           {"values", nlohmann::ordered_json::array()},
                                           {"reasons", nlohmann::ordered_json::array()}},
                                          static_cast<int>(per_group)});
    }
    auto& round_zero = submission.search_groups.back().round_zero;
    round_zero["values"].push_back(c.grid_point[study.search->axis]);
    round_zero["reasons"].push_back("initial");
  }
}

}  // namespace

StudySubmission make_submission(const Study& study) {
  StudySubmission submission;
  submission.hash = study.hash;
  submission.name = study.name;
  submission.description = study.description;
  submission.document = study.document;
  submission.max_attempts = study.max_attempts;
  submission.case_wall_time = study.case_wall_time;
  submission.cases.reserve(study.cases.size());
  for (const auto& study_case : study.cases)
    submission.cases.push_back(
        {study_case.hash, study_case.document, study_case.grid_point, study_case.grid_key, study_case.replicate});
  if (study.search) add_search_groups(study, submission);
  return submission;
}

std::vector<std::string> lost_data_files(const StudySubmission& submission, Store& store, DataFileChecker& checker) {
  // The cases the study expands to, and those a stored copy of it holds besides: the later rounds
  // of a search, which its document does not name.
  std::set<std::string> hashes;
  for (const auto& study_case : submission.cases) hashes.insert(study_case.hash);
  for (auto& hash : store.study_case_hashes(submission.hash)) hashes.insert(std::move(hash));
  std::vector<std::string> lost;
  for (const auto& file : store.data_files({hashes.begin(), hashes.end()})) {
    const auto state = checker.check(file.path, file.digest).state;
    if (state == DataFileState::missing || state == DataFileState::damaged) lost.push_back(file.hash);
  }
  return lost;
}

SubmissionReceipt submit_study(const Study& study, Store& store, DataFileChecker& checker, bool recompute_data_files) {
  StudySubmission submission = make_submission(study);
  const auto lost = lost_data_files(submission, store, checker);
  if (recompute_data_files) submission.recompute = lost;
  auto receipt = store.submit_study(submission);
  receipt.data_files_lost = lost.size();
  return receipt;
}

}  // namespace aerobreak
