#include "orchestrator/export/table_formats.hpp"

namespace aerobreak {

RenderedTable render_table(const LookupTable& table, const ExportRequest& request, std::int64_t study_id) {
  const std::string stem = "study" + std::to_string(study_id) + "_" + table.kind;
  const std::string quantity_stem = stem + "_" + request.quantity;
  switch (request.format) {
    case TableFormat::csv:
      return {csv_text(table), "text/csv; charset=utf-8; header=present", stem + ".csv"};
    case TableFormat::dat:
      return {dat_text(table), "text/plain; charset=utf-8", stem + ".dat"};
    case TableFormat::json:
      return {table_json(table).dump(1) + "\n", "application/json", stem + ".json"};
    case TableFormat::hdf5:
      return {hdf5_image(table), "application/x-hdf5", stem + ".h5"};
    case TableFormat::melcor:
      return {melcor_text(table), "text/plain; charset=utf-8", stem + "_melcor_tf.inp"};
    case TableFormat::openfoam:
      if (request.layout == "csv")
        return {openfoam_csv(table, request.quantity), "text/csv; charset=utf-8", quantity_stem + ".csv"};
      if (request.layout == "dict")
        return {openfoam_dictionary(table, request.quantity, quantity_stem + ".csv"), "text/plain; charset=utf-8",
                quantity_stem + "_function1"};
      return {openfoam_table2d(table, request.quantity), "text/plain; charset=utf-8", quantity_stem + "_table2d"};
    case TableFormat::fortran:
    case TableFormat::c:
      break;  // the code of kind=correlations (correlation_code_file), not of a table
  }
  return {csv_text(table), "text/csv", stem + ".csv"};
}

}  // namespace aerobreak
