#include "orchestrator/service/correlation_endpoints.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "orchestrator/service/http_support.hpp"
#include "orchestrator/study/sha256.hpp"

namespace aerobreak {
namespace {

constexpr std::size_t kMaxCovariateText = 256;
constexpr std::size_t kMaxCovariates = 8;

// ?covariates=a,b (empty: none); absent: the study's default.
std::optional<std::vector<std::string>> covariates_parameter(const httplib::Request& request) {
  const auto given = single_parameter(request, "covariates");
  if (!given) return std::nullopt;
  const std::string& text = *given;
  if (text.size() > kMaxCovariateText)
    throw RequestError{
        400, "query parameter 'covariates' is longer than " + std::to_string(kMaxCovariateText) + " characters"};
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    if (comma == start) throw RequestError{400, "query parameter 'covariates' has an empty name (use a,b,c)"};
    names.push_back(text.substr(start, comma - start));
    if (names.size() > kMaxCovariates)
      throw RequestError{
          400, "query parameter 'covariates' names more than " + std::to_string(kMaxCovariates) + " covariates"};
    start = comma + 1;
  }
  return names;
}

struct CurrentSet {
  std::shared_ptr<const StoredCorrelations> set;
  std::string request_key;
};

CurrentSet current(Endpoints& e, const httplib::Request& request) {
  const auto study = existing_study(e.store, path_id(request));
  try {
    const CorrelationRequest asked = correlation_request(study, covariates_parameter(request));
    return {e.correlations.current(study, asked), request_key(asked)};
  } catch (const CorrelationRequestError& error) {
    // A study without results has no correlations yet: 404, as the dashboard expects of a part it
    // cannot show (docs/WEB.md); the message says why.
    throw RequestError{error.no_results ? 404 : 400, error.what()};
  }
}

// The tag of one document of a stored set: it changes whenever the set is fitted again (its result
// set changed), and only then.
std::string document_tag(const StoredCorrelations& set, const std::string& request_key, const std::string& name) {
  char computed_at[32];
  std::snprintf(computed_at, sizeof computed_at, "%.17g", set.computed_at);
  const std::string identity = request_key + "\n" + set.result_set_hash + "\n" + computed_at + "\n" + name;
  std::string tag(1, '"');
  tag.append(sha256_hex(identity), 0, 32);
  tag.push_back('"');
  return tag;
}

std::string fit_list(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < 20; ++i) text += (i ? ", " : "") + names[i];
  return names.size() > 20 ? text + ", ..." : text;
}

}  // namespace

namespace endpoint {

void get_study_correlations(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto [set, key] = current(e, request);
  send_kept_json(request, response, document_tag(*set, key, ""), set, set->summary);
}

void get_study_correlation(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  const auto [set, key] = current(e, request);
  const std::string name = request.matches[2];
  const auto document = e.store.stored_fit(set->set_id, name);
  if (!document)
    throw RequestError{404, "no fit '" + name + "' among the correlations of study " + std::string(request.matches[1]) +
                                " (fits: " + fit_list(e.store.stored_fit_names(set->set_id)) + ")"};
  auto kept = std::make_shared<const std::string>(std::move(*document));
  send_kept_json(request, response, document_tag(*set, key, name), kept, *kept);
}

}  // namespace endpoint
}  // namespace aerobreak
