#pragma once
#include "orchestrator/store/store_types.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {

// A parsed study and its expanded cases in the form the store takes.
StudySubmission make_submission(const Study& study);

}  // namespace aerobreak
