#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>

#include "orchestrator/app/study_fits.hpp"
#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/store/store.hpp"

// A study's lookup tables (docs/EXPORT.md), the operation that `aerobreak export`, `aerobreak run`
// and GET /api/studies/ID/tables share (docs/ARCHITECTURE.md, the application layer).
namespace aerobreak {

// The lookup table an export asks for, from the store's reader connections: kind grid and sections
// from the stored results, kind fit from the study's stored fits (StudyFits::logistic_fits).
// ExportError on a request the study cannot serve.
LookupTable export_lookup_table(Store& store, StudyFits& fits, const StudyRecord& study, const ExportRequest& request);

// The file an export asks for: a lookup table rendered in its format, or for kind=correlations the
// fitted correlations as code (Fortran, C) or JSON. ExportError on a request the study cannot serve.
RenderedTable export_file(Store& store, StudyFits& fits, const StudyRecord& study, const ExportRequest& request);

// A file as the service keeps it: rendered once, gzip-compressed once, tagged with the result set
// it was made from.
struct KeptFile {
  RenderedTable file;
  std::string gzip_body;
  std::string etag;
};

// The files of the table endpoint, built once per study, result-set version and request and then
// kept (like the correlation documents): at most kMaxFiles of them and kMaxBytes in all; a file
// larger than kMaxFileBytes is built for its request and not kept.
class StudyTables {
 public:
  // `fits` outlives the tables: the study's fits the fit tables and the code read.
  StudyTables(Store& store, StudyFits& fits);
  // `request_key`: the request's canonical text (its parameters, sorted).
  std::shared_ptr<const KeptFile> file(const StudyRecord& study, const ExportRequest& request,
                                       const std::string& request_key);

 private:
  using Key = std::tuple<std::int64_t, std::int64_t, std::string>;  // study, result-set version, request
  std::shared_ptr<const KeptFile> make(const StudyRecord& study, const ExportRequest& request, const Key& key);

  static constexpr std::size_t kMaxFiles = 64;
  static constexpr std::size_t kMaxBytes = 256u << 20;
  static constexpr std::size_t kMaxFileBytes = 32u << 20;
  Store& store_;
  StudyFits& fits_;
  const std::string instance_;  // drawn at start: a tag from another process never matches
  std::mutex mutex_;
  std::map<Key, std::shared_ptr<const KeptFile>> files_;
  std::size_t bytes_ = 0;
};

}  // namespace aerobreak
