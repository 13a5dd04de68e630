// The OpenFOAM tables (docs/EXPORT.md, "OpenFOAM") read by OpenFOAM's own parser: Debian's openfoam
// (scripts/setup.sh installs it) runs foamDictionary on the Function1 csvFile entries and on a
// dictionary that #includes the interpolation2DTable; the values it reads are the table's, and every
// entry asks for outOfBounds error, as the file's header says.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "tests/export/export_study.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

// foamDictionary ARGUMENTS in `directory`, OpenFOAM's environment set up by its bashrc.
CommandOutput foam_dictionary(const ScratchDirectory& directory, const std::string& arguments) {
  const std::string bashrc = AEROBREAK_OPENFOAM_BASHRC;
  INFO("OpenFOAM is needed (scripts/setup.sh installs Debian's openfoam)");
  REQUIRE_FALSE(bashrc.empty());
  return run_command("bash -c 'source " + bashrc + " >/dev/null 2>&1; cd " + directory.path().string() +
                     " && foamDictionary " + arguments + "'");
}

// The numbers of an OpenFOAM list as printed, in order (parentheses dropped).
std::vector<double> numbers_of(const std::string& text) {
  std::string spaced = text;
  for (char& c : spaced)
    if (c == '(' || c == ')') c = ' ';
  std::istringstream words(spaced);
  std::vector<double> numbers;
  for (double x; words >> x;) numbers.push_back(x);
  return numbers;
}

// The numbers of our own text of the list, comments left out.
std::vector<double> numbers_without_comments(const std::string& text) {
  std::istringstream lines(text);
  std::string body;
  for (std::string line; std::getline(lines, line);)
    if (!line.starts_with("//")) body += line + "\n";
  return numbers_of(body);
}

}  // namespace

TEST_CASE("OpenFOAM: its own parser reads the interpolation2DTable and the Function1 entries, outOfBounds error",
          "[export][formats][openfoam]") {
  ScratchDirectory directory("openfoam_parser");
  Store store(directory.path() / "store.sqlite");
  const auto study = fill_wall_study(store);
  ExportRequest request;
  request.select = {{"wall_adhesive", 1}};
  const auto table = study_lookup_table(store, study, request);

  const auto table2d = openfoam_table2d(table, "p_break_up");
  std::ofstream(directory.file("table2d")) << table2d;
  std::ofstream(directory.file("wrapper"))
      << "FoamFile { version 2.0; format ascii; class dictionary; object wrapper; }\n"
         "values\n#include \"table2d\"\n;\n";
  const auto read = foam_dictionary(directory, "wrapper -entry values -value");
  INFO(read.text);
  REQUIRE(read.exit_code == 0);
  const auto parsed = numbers_of(read.text), written = numbers_without_comments(table2d);
  REQUIRE(parsed.size() == written.size());
  REQUIRE(parsed.size() == kSpeeds.size() * (1 + 2 * kSizes.size()));
  for (std::size_t i = 0; i < parsed.size(); ++i)
    CHECK(parsed[i] == Approx(written[i]).epsilon(1e-5));  // printed to 6 digits

  std::ofstream(directory.file("p_break_up.csv")) << openfoam_csv(table, "p_break_up");
  std::ofstream(directory.file("entries")) << openfoam_dictionary(table, "p_break_up", "p_break_up.csv");
  const auto keywords = foam_dictionary(directory, "entries -keywords");
  INFO(keywords.text);
  REQUIRE(keywords.exit_code == 0);
  for (std::size_t k = 1; k <= kSizes.size(); ++k) {
    const std::string entry = "p_break_up_" + std::to_string(k);
    CHECK(keywords.text.find(entry + "\n" + entry + "Coeffs\n") != std::string::npos);
    CHECK(foam_dictionary(directory, "entries -entry " + entry + " -value").text == "csvFile\n");
    CHECK(foam_dictionary(directory, "entries -entry " + entry + "Coeffs/outOfBounds -value").text == "error\n");
    CHECK(foam_dictionary(directory, "entries -entry " + entry + "Coeffs/file -value").text == "\"p_break_up.csv\"\n");
    CHECK(foam_dictionary(directory, "entries -entry " + entry + "Coeffs/componentColumns -value").text ==
          "( " + std::to_string(k) + " )\n");
  }
}

}  // namespace aerobreak::testing
