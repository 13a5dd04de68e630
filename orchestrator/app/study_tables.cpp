#include "orchestrator/app/study_tables.hpp"

#include <random>

#include "orchestrator/app/compression.hpp"
#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/study/sha256.hpp"

namespace aerobreak {
namespace {

std::shared_ptr<const CorrelationSet> fits_of(StudyFits& fits, const StudyRecord& study) {
  try {
    return fits.logistic_fits(study);
  } catch (const CorrelationRequestError& error) {
    throw ExportError(409, "study", error.what());
  }
}

}  // namespace

LookupTable export_lookup_table(Store& store, StudyFits& fits, const StudyRecord& study, const ExportRequest& request) {
  if (request.kind != TableKind::fit) return study_lookup_table(store, study.id, request);
  const auto set = fits_of(fits, study);
  return study_lookup_table(store, study.id, request, set.get());
}

RenderedTable export_file(Store& store, StudyFits& fits, const StudyRecord& study, const ExportRequest& request) {
  if (request.kind == TableKind::correlations)
    return correlation_code_file(store, study.id, request, *fits_of(fits, study));
  return render_table(export_lookup_table(store, fits, study, request), request, study.id);
}

StudyTables::StudyTables(Store& store, StudyFits& fits)
    : store_(store), fits_(fits), instance_(std::to_string(std::random_device{}())) {}

std::shared_ptr<const KeptFile> StudyTables::file(const StudyRecord& study, const ExportRequest& request,
                                                  const std::string& request_key) {
  const auto versions = store_.study_versions(study.id);
  const Key key{study.id, versions ? versions->result_set : 0, request_key};
  {
    std::lock_guard guard(mutex_);
    const auto found = files_.find(key);
    if (found != files_.end()) return found->second;
  }
  return make(study, request, key);
}

std::shared_ptr<const KeptFile> StudyTables::make(const StudyRecord& study, const ExportRequest& request,
                                                  const Key& key) {
  // The version was read before the table: a file may be newer than its tag, never older.
  auto file = std::make_shared<KeptFile>();
  file->file = export_file(store_, fits_, study, request);
  file->gzip_body = gzip(file->file.content);
  file->etag = "\"" + instance_ + "-" + std::to_string(study.id) + "-" + std::to_string(std::get<1>(key)) + "-" +
               sha256_hex(std::get<2>(key)).substr(0, 16) + "\"";
  const std::size_t size = file->file.content.size() + file->gzip_body.size();
  if (size > kMaxFileBytes) return file;
  std::lock_guard guard(mutex_);
  if (files_.size() >= kMaxFiles || bytes_ + size > kMaxBytes) files_.clear(), bytes_ = 0;
  if (files_.emplace(key, file).second) bytes_ += size;
  return file;
}

}  // namespace aerobreak
