#pragma once
#include "orchestrator/store/data_file_check.hpp"
#include "orchestrator/store/store.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {

// A parsed study and its expanded cases in the form the store takes.
StudySubmission make_submission(const Study& study);

// Names in submission.recompute the study's done cases whose data file is missing or damaged, so
// that submitting the study computes them again: the cases its document expands to and, when the
// study is stored already, every case linked to it (a search's later rounds too).
void recompute_lost_data_files(StudySubmission& submission, Store& store, DataFileChecker& checker);

}  // namespace aerobreak
