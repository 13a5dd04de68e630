// Each format of docs/EXPORT.md read back by a consumer: a strict RFC 4180 reader, a Fortran
// program compiled by gfortran with list-directed input, the HDF5 C API, the project's JSON Schema
// validator, and the grammar of OpenFOAM tables (MELCOR's: melcor_format_test.cpp); the fit table's
// `model` column and `fit_models` metadata in each of them; a study on two walls (a boolean axis)
// with its wall_adhesive column in each format, OpenFOAM per wall.
#include <catch2/catch.hpp>
#include <hdf5.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/impact/json_schema.hpp"
#include "engine/io/hdf5_attributes.hpp"
#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/app/study_tables.hpp"
#include "tests/export/export_study.hpp"
#include "tests/export/finite_number.hpp"
#include "tests/export/pooled_size_study.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

using Records = std::vector<std::vector<std::string>>;

// RFC 4180 section 2 as a grammar: records end in CRLF, a field is escaped ("...", quotes doubled,
// may hold commas and line breaks) or not (no comma, quote, CR or LF). Anything else fails.
Records strict_csv(const std::string& text) {
  Records records(1, std::vector<std::string>(1));
  std::size_t i = 0;
  bool field_start = true;
  while (i < text.size()) {
    const char c = text[i];
    if (field_start && c == '"') {
      std::string& field = records.back().back();
      for (++i;; ++i) {
        REQUIRE(i < text.size());
        if (text[i] != '"')
          field += text[i];
        else if (i + 1 < text.size() && text[i + 1] == '"')
          field += '"', ++i;
        else
          break;
      }
      ++i;
      REQUIRE((i == text.size() || text[i] == ',' || text[i] == '\r'));
      field_start = false;
    } else if (c == ',') {
      records.back().emplace_back();
      field_start = true, ++i;
    } else if (c == '\r') {
      REQUIRE(text.substr(i, 2) == "\r\n");
      i += 2;
      if (i < text.size()) records.emplace_back(1);
      field_start = true;
    } else {
      REQUIRE(c != '"');
      REQUIRE(c != '\n');
      records.back().back() += c, ++i, field_start = false;
    }
  }
  return records;
}

struct FormatsFixture {
  ScratchDirectory directory{"table_formats"};
  Store store{directory.path() / "store.sqlite"};
  std::int64_t study = fill_export_study(store);
  LookupTable table(ExportRequest request = {}) { return study_lookup_table(store, study, request); }
};

ExportRequest with_material() {
  ExportRequest request;
  request.material = ExportMaterial{{1e10, 0.3, 1725.0, 0.001 * 1e10 * 2e-8 / 2.73}, 2e-8};
  return request;
}

void check_value(double read, double written) {
  if (std::isnan(written)) {
    CHECK(std::isnan(read));
    return;
  }
  // Written with 10 significant digits (%.9e): read back within half a unit of the last one.
  CHECK(read == Approx(written).epsilon(5.1e-10).margin(1e-300));
}

// tests/export/read_lookup_dat.f90 compiled by gfortran into the directory: the reader's path.
std::string compiled_dat_reader(const ScratchDirectory& directory) {
  const std::string gfortran = AEROBREAK_GFORTRAN;
  INFO("gfortran is needed (scripts/setup.sh installs it)");
  REQUIRE_FALSE(gfortran.empty());
  const auto reader = directory.file("read_lookup_dat");
  // Built to stop on any invalid operation, division by zero or overflow: a NaN in the file would.
  const auto compiled = run_command(gfortran + " -O0 -std=f2008 -ffpe-trap=invalid,zero,overflow -o " + reader +
                                    " " AEROBREAK_SOURCE_DIR "/tests/export/read_lookup_dat.f90");
  INFO(compiled.text);
  REQUIRE(compiled.exit_code == 0);
  return reader;
}

// The Fortran reader reads the index (each column's number, name and unit, list-directed) and every
// value of the .dat file, row by row, as the table has it, the sentinel where a value is missing;
// no line of the file is longer than 80 characters.
void check_dat_read_back(const std::string& reader, const std::string& dat_file, const LookupTable& table) {
  std::ifstream file(dat_file);
  for (std::string line; std::getline(file, line);) CHECK(line.size() <= kDatLineWidth);
  const auto read = run_command(reader + " " + dat_file, true);
  REQUIRE(read.exit_code == 0);
  std::istringstream lines(read.text);
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    std::string line;
    REQUIRE(std::getline(lines, line));
    CHECK(line == "column " + std::to_string(c + 1) + " " + table.columns[c].name + " " + table.columns[c].unit);
  }
  for (std::size_t row = 0; row < table.rows(); ++row)
    for (const auto& column : table.columns) {
      std::string line;
      REQUIRE(std::getline(lines, line));
      const double written = column.values[row];
      check_value(std::strtod(line.c_str(), nullptr), std::isnan(written) ? kDatMissingValue : written);
    }
  std::string last;
  std::getline(lines, last);
  CHECK(last == "rows " + std::to_string(table.rows()));
}

}  // namespace

TEST_CASE("CSV: a strict RFC 4180 reader finds the header block, names, units and every value", "[export][formats]") {
  FormatsFixture fixture;
  for (const auto& request : {ExportRequest{}, with_material()}) {
    const auto table = fixture.table(request);
    const auto records = strict_csv(csv_text(table));
    for (const auto& record : records) CHECK(record.size() == table.columns.size());
    REQUIRE(records[0][0] == "#header_lines");
    const std::size_t header = std::stoul(records[0][1]);
    for (std::size_t r = 0; r < header; ++r) CHECK(records[r][0].starts_with("#"));
    REQUIRE(records.size() == header + 2 + table.rows());
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      CHECK(records[header][c] == table.columns[c].name);
      CHECK(records[header + 1][c] == table.columns[c].unit);
      for (std::size_t row = 0; row < table.rows(); ++row) {
        const auto& field = records[header + 2 + row][c];
        if (std::isnan(table.columns[c].values[row]))
          CHECK(field.empty());
        else
          check_value(std::stod(field), table.columns[c].values[row]);
      }
    }
    bool hash_found = false;
    for (std::size_t r = 0; r < header; ++r) hash_found = hash_found || records[r][0] == "#provenance.study_hash";
    CHECK(hash_found);
  }
}

TEST_CASE(".dat: a Fortran program (gfortran, list-directed input) reads every value to the printed precision",
          "[export][formats]") {
  FormatsFixture fixture;
  const auto reader = compiled_dat_reader(fixture.directory);
  for (const char* kind : {"grid", "sections"}) {
    const auto dat = fixture.directory.file(std::string(kind) + ".dat");
    const auto exported =
        run_command(std::string(AEROBREAK_BINARY) + " export --store " + fixture.directory.file("store.sqlite") +
                    " --kind " + kind + " --format dat --youngs-modulus 1e10 --poisson-ratio 0.3 --density 1725" +
                    " --surface-energy " + std::to_string(0.001 * 1e10 * 2e-8 / 2.73) + " --diameter 2e-8 -o " + dat);
    INFO(exported.text);
    REQUIRE(exported.exit_code == 0);
    auto request = with_material();
    request.kind = std::string(kind) == "grid" ? TableKind::grid : TableKind::sections;
    check_dat_read_back(reader, dat, fixture.table(request));
  }
}

TEST_CASE("JSON: valid against schemas/lookup.schema.json, values as in the table", "[export][formats]") {
  FormatsFixture fixture;
  std::ifstream file(AEROBREAK_SOURCE_DIR "/schemas/lookup.schema.json");
  const JsonSchema schema(nlohmann::ordered_json::parse(file));
  for (const auto kind : {TableKind::grid, TableKind::sections}) {
    auto request = with_material();
    request.kind = kind;
    const auto table = fixture.table(request);
    const auto document = nlohmann::ordered_json::parse(table_json(table).dump());
    CHECK(describe(schema.validate(document)).empty());
    REQUIRE(document.at("columns").size() == table.columns.size());
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      for (std::size_t row = 0; row < table.rows(); ++row) {
        const auto& value = document.at("columns")[c].at("values")[row];
        if (std::isnan(table.columns[c].values[row]))
          CHECK(value.is_null());
        else
          CHECK(value.get<double>() == table.columns[c].values[row]);
      }
  }
  auto broken = table_json(fixture.table());
  broken["columns"][0].erase("unit");
  CHECK_FALSE(schema.validate(nlohmann::ordered_json::parse(broken.dump())).empty());
}

TEST_CASE("HDF5: the C API reads one dataset per column with its units, and the provenance", "[export][formats]") {
  FormatsFixture fixture;
  const auto table = fixture.table(with_material());
  const auto path = fixture.directory.path() / "table.h5";
  std::ofstream(path, std::ios::binary) << hdf5_image(table);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  CHECK(read_string_attribute(file, "provenance.study_hash") == std::vector<std::string>{std::string(64, 'e')});
  CHECK(read_string_attribute(file, "units") == std::vector<std::string>{"reduced and SI"});
  for (const auto& column : table.columns) {
    const hid_t dataset = H5Dopen2(file, column.name.c_str(), H5P_DEFAULT);
    REQUIRE(dataset >= 0);
    std::vector<double> values(table.rows());
    REQUIRE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
    for (std::size_t row = 0; row < values.size(); ++row)
      CHECK((values[row] == column.values[row] || (std::isnan(values[row]) && std::isnan(column.values[row]))));
    CHECK(read_string_attribute(dataset, "units") == std::vector<std::string>{column.unit});
    H5Dclose(dataset);
  }
  H5Fclose(file);
}

namespace {

// The text without comments (from `marker` to the end of a line), as whitespace-separated tokens.
std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++count;
  return count;
}

std::vector<std::string> tokens(const std::string& text, const std::string& marker) {
  std::vector<std::string> words;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words_of(line.substr(0, line.find(marker)));
    for (std::string word; words_of >> word;) words.push_back(word);
  }
  return words;
}

}  // namespace

TEST_CASE("OpenFOAM: interpolation2DTable ascending in both, csvFile data and entries that match it",
          "[export][formats]") {
  FormatsFixture fixture;
  const auto table = fixture.table(with_material());
  const auto words = tokens(openfoam_table2d(table, "p_break_up"), "//");
  // ( (x ( (y v) (y v) )) ... ): parentheses as tokens of their own after spacing them out.
  std::string spaced;
  for (const auto& word : words) spaced += word + " ";
  std::vector<std::string> parts;
  std::string current;
  for (const char c : spaced) {
    if (c == '(' || c == ')' || c == ' ') {
      if (!current.empty()) parts.push_back(current), current.clear();
      if (c != ' ') parts.emplace_back(1, c);
    } else
      current += c;
  }
  std::size_t i = 0;
  REQUIRE(parts.at(i++) == "(");
  double previous_x = -INFINITY;
  std::size_t rows = 0;
  while (parts.at(i) == "(") {
    ++i;
    const double x = finite_number(parts.at(i++));
    CHECK(x > previous_x);
    previous_x = x;
    REQUIRE(parts.at(i++) == "(");
    double previous_y = -INFINITY;
    std::size_t entries = 0;
    while (parts.at(i) == "(") {
      const double y = finite_number(parts.at(i + 1));
      finite_number(parts.at(i + 2));
      REQUIRE(parts.at(i + 3) == ")");
      CHECK(y > previous_y);
      previous_y = y;
      i += 4, ++entries;
    }
    CHECK(entries == kSizes.size());
    REQUIRE(parts.at(i++) == ")");
    REQUIRE(parts.at(i++) == ")");
    ++rows;
  }
  REQUIRE(parts.at(i++) == ")");
  CHECK(i == parts.size());
  CHECK(rows == kSpeeds.size());

  const auto csv = openfoam_csv(table, "retained_mass_fraction");
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  const auto columns = static_cast<std::size_t>(std::count(line.begin(), line.end(), ',') + 1);
  CHECK(columns == 1 + kSizes.size());
  double previous = -INFINITY;
  std::size_t data_rows = 0;
  while (std::getline(lines, line)) {
    CHECK(static_cast<std::size_t>(std::count(line.begin(), line.end(), ',') + 1) == columns);
    const double x = finite_number(line.substr(0, line.find(',')));
    CHECK(x > previous);
    previous = x, ++data_rows;
  }
  CHECK(data_rows == kSpeeds.size());
  const auto dictionary = openfoam_dictionary(table, "retained_mass_fraction", "r.csv");
  CHECK(std::count(dictionary.begin(), dictionary.end(), '{') == static_cast<long>(kSizes.size()));
  CHECK(dictionary.find("componentColumns    (" + std::to_string(kSizes.size()) + ");") != std::string::npos);
  CHECK(dictionary.find("componentColumns    (" + std::to_string(kSizes.size() + 1) + ");") == std::string::npos);
  // Behaviour and header agree: nothing clamped outside the table, and the header says so.
  CHECK(static_cast<std::size_t>(std::count(dictionary.begin(), dictionary.end(), '{')) ==
        count_of(dictionary, "outOfBounds         error;"));
  CHECK(count_of(dictionary, "outOfBounds         clamp") == 0);
  for (const auto& text : {dictionary, openfoam_table2d(table, "p_break_up")})
    CHECK(text.find("// outside its speeds and sizes this table has no value: read it with outOfBounds error") !=
          std::string::npos);

  try {
    openfoam_table2d(fixture.table(), "p_stick");  // both gamma/k_n: two conditions
    FAIL("an OpenFOAM table of two conditions was written");
  } catch (const ExportError& error) {
    CHECK(error.status == 422);
  }
}

TEST_CASE("Fit table with a size not run: the model column and fit_models in every format", "[export][formats][fit]") {
  ScratchDirectory directory("table_formats_fit");
  Store store(directory.path() / "store.sqlite");
  const std::int64_t study = fill_pooled_study(store);
  ExportRequest request;
  request.kind = TableKind::fit;
  request.speeds = {0.02, 0.05, 0.1};
  request.sizes = {32, 64, 128};
  StudyFits fits(store);
  const auto table = export_lookup_table(store, fits, *store.study(study), request);
  const auto model =
      std::find_if(table.columns.begin(), table.columns.end(), [](const TableColumn& c) { return c.name == "model"; });
  REQUIRE(model != table.columns.end());
  CHECK(std::prev(model)->name == "inside_validity");
  CHECK(model->values == std::vector<double>{0, 0, 0, 1, 1, 1, 0, 0, 0});  // 64 was not run
  CHECK(csv_text(table).find("#fit_models.pooled_ln_n,") != std::string::npos);
  const auto dat = dat_text(table);
  const auto model_number = std::to_string(model - table.columns.begin() + 1);
  CHECK(dat.find("# column " + model_number + " model '1'\n") != std::string::npos);
  const auto dat_file = directory.file("fit.dat");
  std::ofstream(dat_file) << dat;
  check_dat_read_back(compiled_dat_reader(directory), dat_file, table);
  std::ifstream schema_file(AEROBREAK_SOURCE_DIR "/schemas/lookup.schema.json");
  const JsonSchema schema(nlohmann::ordered_json::parse(schema_file));
  const auto document = nlohmann::ordered_json::parse(table_json(table).dump());
  CHECK(describe(schema.validate(document)).empty());
  CHECK(document.at("metadata").at("fit_models").at("column") == "model: 0 = per_size, 1 = pooled_ln_n");
  const auto h5 = directory.path() / "fit.h5";
  std::ofstream(h5, std::ios::binary) << hdf5_image(table);
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(file >= 0);
  CHECK(read_string_attribute(file, "fit_models.column") ==
        std::vector<std::string>{"model: 0 = per_size, 1 = pooled_ln_n"});
  H5Fclose(file);
  const auto melcor = melcor_text(table);
  CHECK(melcor.find("! fit_models.pooled_ln_n: ") != std::string::npos);
  CHECK(melcor.find("primaries = 6.400000000e+01, model = 1.000000000e+00") != std::string::npos);
  const auto openfoam = openfoam_table2d(table, "p_break_up");  // one condition: the model varies with the size
  CHECK(openfoam.find("// fit_models.per_size: ") != std::string::npos);
  std::size_t opened = 0;
  for (const auto& word : tokens(openfoam, "//"))
    opened += static_cast<std::size_t>(std::count(word.begin(), word.end(), '('));
  CHECK(opened == 1 + 3 * 2 + 3 * 3);  // the list, per speed two, per (speed, size) one
}

namespace {

struct WallFormatsFixture {
  ScratchDirectory directory{"table_formats_walls"};
  Store store{directory.path() / "store.sqlite"};
  std::int64_t study = fill_wall_study(store);
  LookupTable table(ExportRequest request = {}) { return study_lookup_table(store, study, request); }
};

// The values of the column `name` in records (a header row, a units row, then the rows) of a CSV.
std::vector<double> csv_column(const Records& records, const std::string& name) {
  const std::size_t header = std::stoul(records[0][1]);
  const auto& names = records[header];
  const auto c = static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  REQUIRE(c < names.size());
  std::vector<double> values;
  for (std::size_t r = header + 2; r < records.size(); ++r) values.push_back(std::stod(records[r][c]));
  return values;
}

}  // namespace

TEST_CASE("Two walls: wall_adhesive (1/0) is a column of the grid and sections tables in CSV, .dat, JSON and HDF5",
          "[export][formats][axes]") {
  WallFormatsFixture fixture;
  const auto reader = compiled_dat_reader(fixture.directory);
  std::ifstream schema_file(AEROBREAK_SOURCE_DIR "/schemas/lookup.schema.json");
  const JsonSchema schema(nlohmann::ordered_json::parse(schema_file));
  for (const char* kind : {"grid", "sections"}) {
    INFO(kind);
    ExportRequest request;
    request.kind = std::string(kind) == "grid" ? TableKind::grid : TableKind::sections;
    const auto table = fixture.table(request);
    const auto* wall = table.find("wall_adhesive");
    REQUIRE(wall);
    REQUIRE(table.rows() == kSpeeds.size() * kSizes.size() * 2);
    CHECK(std::count(wall->values.begin(), wall->values.end(), 1.0) ==
          static_cast<long>(kSpeeds.size() * kSizes.size()));
    CHECK(csv_column(strict_csv(csv_text(table)), "wall_adhesive") == wall->values);
    const auto dat = fixture.directory.file(std::string(kind) + ".dat");
    const auto exported =
        run_command(std::string(AEROBREAK_BINARY) + " export --store " + fixture.directory.file("store.sqlite") +
                    " --kind " + kind + " --format dat -o " + dat);
    INFO(exported.text);
    REQUIRE(exported.exit_code == 0);
    check_dat_read_back(reader, dat, table);
    const auto document = nlohmann::ordered_json::parse(table_json(table).dump());
    CHECK(describe(schema.validate(document)).empty());
    const auto column = std::find_if(document.at("columns").begin(), document.at("columns").end(),
                                     [](const auto& c) { return c.at("name") == "wall_adhesive"; });
    REQUIRE(column != document.at("columns").end());
    CHECK(column->at("role") == "input");
    CHECK(column->at("values").get<std::vector<double>>() == wall->values);
    auto labelled = document;  // a text axis's codes (docs/EXPORT.md "Axis columns"): strings only
    labelled["metadata"]["axis_labels"] = {{"generator", {"ballistic", "dlca"}}};
    CHECK(describe(schema.validate(labelled)).empty());
    labelled["metadata"]["axis_labels"]["generator"] = {1, 2};
    CHECK_FALSE(schema.validate(labelled).empty());
    const auto h5 = fixture.directory.path() / (std::string(kind) + ".h5");
    std::ofstream(h5, std::ios::binary) << hdf5_image(table);
    const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(file >= 0);
    const hid_t dataset = H5Dopen2(file, "wall_adhesive", H5P_DEFAULT);
    REQUIRE(dataset >= 0);
    std::vector<double> values(table.rows());
    CHECK(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
    CHECK(values == wall->values);
    CHECK(read_string_attribute(dataset, "description") == std::vector<std::string>{wall->description});
    H5Dclose(dataset);
    H5Fclose(file);
  }
}

TEST_CASE("Two walls: OpenFOAM refuses naming wall_adhesive until select picks one", "[export][formats][axes]") {
  WallFormatsFixture fixture;
  for (const auto kind : {TableKind::grid, TableKind::sections}) {
    ExportRequest request;
    request.kind = kind;
    const auto table = fixture.table(request);
    try {
      openfoam_table2d(table, "p_break_up");
      FAIL("an OpenFOAM table of two walls was written");
    } catch (const ExportError& error) {
      CHECK(error.status == 422);
      CHECK(error.field == "format");
      CHECK_THAT(error.what(),
                 Catch::Contains("differing in wall_adhesive") && Catch::Contains("select=wall_adhesive:1"));
    }
    request.select = {{"wall_adhesive", 0}};
    const auto bare_wall = openfoam_table2d(fixture.table(request), "p_break_up");
    // Without adhesion, N = 32 (d_ve = 32^(1/3), also the lower bound of its section [32, 64)) at
    // the fastest speed: two of four break up (wall_fragments_of).
    CHECK(bare_wall.find("(" + number_text(std::cbrt(32.0)) + " " + number_text(0.5) + ")") != std::string::npos);
  }
}

}  // namespace aerobreak::testing
