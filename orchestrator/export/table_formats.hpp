#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "orchestrator/export/export_request.hpp"
#include "orchestrator/export/lookup_table.hpp"

namespace aerobreak {

// A lookup table written in one format (docs/EXPORT.md, "Formats").
struct RenderedTable {
  std::string content;       // bytes
  std::string content_type;  // of the HTTP answer
  std::string file_name;     // suggested: studyID_KIND[_QUANTITY].EXT
};

// RFC 4180 CSV (CRLF line ends, quoted where needed): "#key,value" metadata records padded to the
// column count, of which the first gives header_lines (records before the names), the column
// names, their units, the rows.
std::string csv_text(const LookupTable& table);
// Whitespace-separated columns for Fortran list-directed input, safe for older Fortran: no line
// longer than kDatLineWidth characters (a row continues over lines of kDatValuesPerLine values, one
// list-directed READ of C values reads it), comment lines start with '#' (the second gives their
// number: "# header_lines: H"), index lines "# column I NAME 'UNIT'" that a list-directed READ
// takes as they are, no quotes in the rows, no empty field and no NaN: a missing value is the
// sentinel kDatMissingValue.
inline constexpr std::size_t kDatLineWidth = 80;
inline constexpr std::size_t kDatValuesPerLine = 4;
inline constexpr double kDatMissingValue = -1.0e30;
std::string dat_text(const LookupTable& table);
// schemas/lookup.schema.json.
nlohmann::ordered_json table_json(const LookupTable& table);
// An HDF5 file image: one dataset per column (attributes units, description, role), the metadata
// as attributes of the root group.
std::string hdf5_image(const LookupTable& table);
// MELCOR 2 tabular functions (TF_INPUT / TF_ID / TF_TAB): one function per quantity (every
// outcome's probability and its 95 % interval ends, the restitution, the retained mass, the
// sectional matrix) and impact condition, x = impact speed (m/s when SI, else d/tau), ascending;
// named S<study><kind><quantity><bound><condition> (docs/EXPORT.md), unique across studies, table
// kinds, quantities and conditions, at most kMelcorNameLength characters (ExportError 422 beyond).
inline constexpr std::size_t kMelcorNameLength = 16;
std::string melcor_text(const LookupTable& table);
// OpenFOAM interpolation2DTable of `quantity` over (impact speed, volume-equivalent diameter), the
// CSV data of a Function1 csvFile (speed, then one column per size), or the Function1 entries
// that read that CSV file. ExportError 422 when the table holds more than one impact condition
// besides speed and size (choose one with a material or gamma_over_kn).
std::string openfoam_table2d(const LookupTable& table, const std::string& quantity);
std::string openfoam_csv(const LookupTable& table, const std::string& quantity);
std::string openfoam_dictionary(const LookupTable& table, const std::string& quantity, const std::string& csv_file);

RenderedTable render_table(const LookupTable& table, const ExportRequest& request, std::int64_t study_id);

}  // namespace aerobreak
