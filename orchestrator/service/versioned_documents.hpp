#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <httplib.h>

#include "orchestrator/store/store.hpp"

namespace aerobreak {

// A serialised document about a study and the versions of the study it was made from.
struct VersionedDocument {
  StudyVersions versions;
  std::string etag;
  std::string body;
  std::string gzip_body;  // the body gzip-compressed once, for clients that accept gzip
};

// The latest document of one kind (the outcome table, the dashboard's grid statistics) for each
// study asked for, at most kMaxStudies of them, served with an ETag made of the study's versions
// (Store::study_versions: raised in the same transactions as the cases and results they count).
// ETags carry a token drawn when the service starts, so that a tag from another process (another
// store on the same port) never matches. The body is compressed once per version (gzip) and sent
// as it is: left to cpp-httplib, a large answer (the dashboard's grid of a 100,000-case study,
// 2.7 MB) was compressed again on every request at Brotli's slowest setting, seconds each.
class VersionedDocuments {
 public:
  using Build = std::function<std::string(std::int64_t study)>;
  explicit VersionedDocuments(Build build);

  // Answers GET for `study`: 404 when there is no such study, 304 when the request's If-None-Match
  // names the current tag, else 200 with the document (built again only when the versions moved).
  void serve(Store& store, std::int64_t study, const httplib::Request& request, httplib::Response& response);

 private:
  std::shared_ptr<const VersionedDocument> find(std::int64_t study, const StudyVersions& versions) const;
  std::shared_ptr<const VersionedDocument> make(std::int64_t study, const StudyVersions& versions);

  static constexpr std::size_t kMaxStudies = 64;
  const Build build_;
  const std::string instance_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, std::shared_ptr<const VersionedDocument>> documents_;
};

}  // namespace aerobreak
