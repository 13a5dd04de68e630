#include "orchestrator/service/study_submission.hpp"

namespace aerobreak {

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
  return submission;
}

void recompute_lost_data_files(StudySubmission& submission, Store& store, DataFileChecker& checker) {
  std::vector<std::string> hashes;
  hashes.reserve(submission.cases.size());
  for (const auto& study_case : submission.cases) hashes.push_back(study_case.hash);
  for (const auto& file : store.data_files(hashes)) {
    const auto state = checker.check(file.path, file.digest).state;
    if (state == DataFileState::missing || state == DataFileState::damaged) submission.recompute.push_back(file.hash);
  }
}

}  // namespace aerobreak
