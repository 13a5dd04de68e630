// kind=correlations (docs/EXPORT.md, "Correlations as code"): the study's fits as a Fortran 90
// module, a C header or their JSON description, with the study's provenance and units.
#include "engine/core/version.hpp"
#include "orchestrator/export/correlation_code.hpp"
#include "orchestrator/export/lookup_tables.hpp"

namespace aerobreak {
namespace {

std::vector<std::string> code_header(const StudyExportData& data, bool physical) {
  std::vector<std::string> header{
      "Study " + std::to_string(data.study.id) + " '" + data.study.name + "' (hash " + data.study.hash +
          "), result-set version " + std::to_string(data.versions.result_set) + ", aerobreak " +
          std::string(version()) + " (" + std::string(git_commit()) + ").",
      std::string("Units: v impact speed in ") +
          (physical ? "m/s" : "d/tau (reduced: d primary diameter, tau = sqrt(m/k_n))") +
          "; n primaries per cluster (any positive real); P and its band dimensionless.",
      "Each function returns P (or v50), sets lo and hi to its 95 % interval, inside to whether (v, n) lies in the "
      "fit's "
      "validity box (outside: an extrapolation of the fitted form), and status to where the value comes from."};
  if (physical) {
    const auto& scaling = *data.inputs.front().scaling;
    header.push_back(
        "Sizes (docs/EXPORT.md section 2): primary diameter d = " + number_text(scaling.diameter) +
        " m; volume-equivalent diameter d_ve = d n^(1/3); mobility diameter d_mob = d n^(1/(2 x 1.08)), so "
        "n = (d_mob/d)^2.16.");
  }
  return header;
}

}  // namespace

RenderedTable correlation_code_file(Store& store, std::int64_t study_id, const ExportRequest& request,
                                    const CorrelationSet& fits) {
  const auto data = read_study_export_data(store, study_id);
  const bool physical = !data.inputs.empty() && data.inputs.front().scaling.has_value();
  const auto code = correlation_code(fits, study_id, physical ? "m/s" : "d/tau", code_header(data, physical));
  const std::string stem = "study" + std::to_string(study_id) + "_correlations";
  if (request.format == TableFormat::fortran)
    return {fortran_module(code), "text/x-fortran; charset=utf-8", stem + ".f90"};
  if (request.format == TableFormat::c) return {c_header(code), "text/x-c; charset=utf-8", stem + ".h"};
  return {code_json(code).dump(1) + "\n", "application/json", stem + ".json"};
}

}  // namespace aerobreak
