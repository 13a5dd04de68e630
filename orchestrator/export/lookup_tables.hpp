#pragma once
#include <cstdint>

#include "orchestrator/export/export_request.hpp"
#include "orchestrator/export/lookup_table.hpp"
#include "orchestrator/export/study_export_data.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// The fitted correlations of a study (orchestrator/fitting/correlation_set.hpp, which brings Eigen:
// not included here, so that this header can follow cpp-httplib's, whose <resolv.h> defines _res).
struct CorrelationSet;

// Table (a): one row per grid point of the study, inputs and outcome statistics (reduced units);
// of an adaptive search, with metadata search.axis and search.note (kSearchedGridNote).
LookupTable grid_table(const StudyExportData& data);

// What a grid table of an adaptive search holds, and the table to read instead.
inline constexpr const char* kSearchedGridNote =
    "an adaptive search placed one or a few cases at each value of its axis: a row per value it ran, each "
    "probability of few results; the fit table (kind=fit) gives the fitted curves for a system code";

// Table (c): the sectional fragment matrix for geometric sections of mass ratio `section_ratio`
// (reduced units): one row per impact condition and source section, the mass fractions that end
// on the wall and in each section (a column of the matrix; they sum to 1).
LookupTable sections_table(const StudyExportData& data, double section_ratio);

// Table (b): P(stick) and P(break-up) from the logistic fits in impact speed, at the request's
// speeds (default: 25 log-spaced over each fit's validity box) and sizes (default: those the study
// ran), with their 95 % bands, a validity flag and the model of each row: a size the study ran from
// its per-group fits, one it did not run from the fits pooled over its sizes per condition of the
// other axes (OUTCOME.speed.pooled.cK with ln N its one covariate). strict refuses a row outside a fit's validity box
// (ExportError 422 naming speeds or sizes); a size without a usable fit is refused (422, sizes).
// `speed_unit_of_study`: d/tau in the study's speed unit (m/s for a physical study, 1 for a reduced one).
LookupTable fit_table(const CorrelationSet& set, const ExportRequest& request, double speed_unit_of_study);

// The rows of a material's gamma/k_n (docs/EXPORT.md "Units"): those at the study's value within
// a relative 1e-3, or interpolated linearly in ln(gamma/k_n) between the two bracketing values when
// `interpolate`; ExportError 422 naming surface_energy otherwise.
// `material` gives nu for lambda (eq 19) of interpolated rows.
LookupTable rows_for_gamma(const LookupTable& table, const Material& material, double gamma_over_kn, bool interpolate);

// The rows whose input columns have the values of `select` (select=NAME:VALUE, e.g. one wall);
// ExportError 422 naming select for a name that is no input column or when no row matches.
LookupTable selected_rows(const LookupTable& table, const std::vector<std::pair<std::string, double>>& select);

// Adds after each column in d/tau its value in m/s, after each in d its value in m, with the
// scaling of each row.
void add_si_columns(LookupTable& table, const std::vector<PhysicalScaling>& scalings);

// What the export of `request` from study `study_id` tabulates, units applied and metadata filled
// in; kind fit needs the study's fitted correlations (`fits`). ExportError on a request the study
// cannot serve.
LookupTable study_lookup_table(Store& store, std::int64_t study_id, const ExportRequest& request,
                               const CorrelationSet* fits = nullptr);

// kind=correlations: the study's fits as code (format fortran or c) or its JSON description
// (correlation_code.hpp), headed by the study's provenance and units.
RenderedTable correlation_code_file(Store& store, std::int64_t study_id, const ExportRequest& request,
                                    const CorrelationSet& fits);

}  // namespace aerobreak
