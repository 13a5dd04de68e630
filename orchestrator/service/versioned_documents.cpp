#include "orchestrator/service/versioned_documents.hpp"

#include <random>
#include <utility>

#include "orchestrator/app/compression.hpp"
#include "orchestrator/service/http_support.hpp"

namespace aerobreak {

VersionedDocuments::VersionedDocuments(Build build)
    : build_(std::move(build)), instance_(std::to_string(std::random_device{}())) {}

std::shared_ptr<const VersionedDocument> VersionedDocuments::find(std::int64_t study,
                                                                  const StudyVersions& versions) const {
  std::lock_guard lock(mutex_);
  const auto found = documents_.find(study);
  if (found == documents_.end() || found->second->versions.case_states != versions.case_states ||
      found->second->versions.result_set != versions.result_set)
    return nullptr;
  return found->second;
}

std::shared_ptr<const VersionedDocument> VersionedDocuments::make(std::int64_t study, const StudyVersions& versions) {
  // The versions were read before the document: a document may be newer than its tag, never older,
  // so that a client holding the tag is never told an out-of-date document is current.
  std::string body = build_(study);
  std::string compressed = gzip(body);
  auto document = std::make_shared<const VersionedDocument>(
      VersionedDocument{versions,
                        "\"" + instance_ + "-" + std::to_string(study) + "-" + std::to_string(versions.case_states) +
                            "-" + std::to_string(versions.result_set) + "\"",
                        std::move(body), std::move(compressed)});
  std::lock_guard lock(mutex_);
  if (documents_.size() >= kMaxStudies) documents_.clear();
  documents_[study] = document;
  return document;
}

void VersionedDocuments::serve(Store& store, std::int64_t study, const httplib::Request& request,
                               httplib::Response& response) {
  const auto versions = store.study_versions(study);
  if (!versions) throw RequestError{404, "no study " + std::to_string(study)};
  auto document = find(study, *versions);
  if (!document) document = make(study, *versions);
  response.set_header("Vary", "Accept-Encoding");
  if (accepts_gzip(request))
    send_kept_json(request, response, document->etag, document, document->gzip_body, "gzip");
  else
    send_kept_json(request, response, document->etag, document, document->body);
}

}  // namespace aerobreak
