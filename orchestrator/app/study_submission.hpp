#pragma once
#include "orchestrator/store/data_file_check.hpp"
#include "orchestrator/store/store.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {

// A parsed study and its expanded cases in the form the store takes.
StudySubmission make_submission(const Study& study);

// The hashes of the study's done cases whose data file is missing or damaged: of the cases its
// document expands to and, when the study is stored already, of every case linked to it (a
// search's later rounds too). Their results stay; a submitter who asks for it names them in
// submission.recompute, so that they are computed again.
std::vector<std::string> lost_data_files(const StudySubmission& submission, Store& store, DataFileChecker& checker);

// Submits a parsed study to the store: its cases (those already done are kept), a search's round 0,
// and, with `recompute_data_files`, the done cases whose data file is lost computed again. The
// receipt counts the lost data files either way. What `aerobreak run` and POST /api/studies do.
SubmissionReceipt submit_study(const Study& study, Store& store, DataFileChecker& checker, bool recompute_data_files);

}  // namespace aerobreak
