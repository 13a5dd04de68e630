// The fitted correlations as code (docs/EXPORT.md, "Correlations as code") read by their real
// consumers, on a study of two walls and two sizes served by `aerobreak serve`: the Fortran module
// compiled by gfortran (trapping invalid operations) and the C header by gcc (-std=c99 -pedantic
// -Werror) into programs that evaluate every generated function at seeded random points inside the
// validity box and one outside, compared with the service's fit table at the same points
// (GET .../tables?kind=fit&format=json) to 1e-12 relative, status and validity flag included; the
// v50 functions against the critical values of the fits served under /correlations; the JSON
// description valid against schemas/correlation_code.schema.json.
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "engine/impact/json_schema.hpp"
#include "tests/export/pooled_size_study.hpp"
#include "tests/orchestrator/service_process.hpp"
#include "tests/support/run_command.hpp"

namespace aerobreak::testing {
namespace {

constexpr double kRelative = 1e-12;

struct Point {
  double v, n;
};

// One line of a driver's output: what a function gave at a point.
struct Evaluation {
  double value, lo, hi;
  bool inside;
  int status;
};
using Evaluations = std::map<std::string, Evaluation>;  // "function v n" (or "function n") -> values

std::string text_of(const ServiceProcess& service, const std::string& path) {
  auto client = service.client();
  const auto response = client.Get(path.c_str());
  REQUIRE(response);
  INFO(path << " -> " << response->body.substr(0, 300));
  REQUIRE(response->status == 200);
  return response->body;
}

std::string key(const std::string& function, double a, double b = NAN) {
  char text[160];
  std::snprintf(text, sizeof text, "%s %.17g %.17g", function.c_str(), a, b);
  return text;
}

// The driver's lines: NAME A B VALUE LO HI INSIDE(T/F or 1/0) STATUS (B is - for v50).
Evaluations parse_output(const std::string& output) {
  Evaluations evaluations;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string name, a, b, inside;
    Evaluation e{};
    words >> name >> a >> b >> e.value >> e.lo >> e.hi >> inside >> e.status;
    REQUIRE(words);
    e.inside = inside == "T" || inside == "1";
    evaluations[key(name, std::stod(a), b == "-" ? NAN : std::stod(b))] = e;
  }
  return evaluations;
}

std::string fortran_driver(const Json& description, const std::vector<Point>& points,
                           const std::vector<double>& sizes) {
  std::string text =
      "program drive\n  use aerobreak_study1\n  implicit none\n  integer, parameter :: dp = kind(1.0d0)\n"
      "  real(dp) :: value, lo, hi\n  logical :: inside\n  integer :: status\n";
  const auto literal = [](double x) {
    char s[40];
    std::snprintf(s, sizeof s, "%.17e", x);
    std::string t = s;
    t[t.find('e')] = 'd';
    return t;
  };
  const std::string format = "'(A,1X,ES25.16E3,1X,ES25.16E3,3(1X,ES25.16E3),1X,L1,1X,I0)'";
  for (const auto& f : description.at("functions")) {
    const std::string p = f.at("p"), v50 = f.at("v50");
    for (const auto& point : points)
      text += "  value = " + p + "(" + literal(point.v) + ", " + literal(point.n) +
              ", lo, hi, inside, status)\n  write(*, " + format + ") &\n    '" + p + "', " + literal(point.v) + ", " +
              literal(point.n) + ", &\n    value, lo, hi, inside, status\n";
    for (const double n : sizes)
      text += "  value = " + v50 + "(" + literal(n) + ", lo, hi, inside, status)\n  write(*, " +
              "'(A,1X,ES25.16E3,1X,A,3(1X,ES25.16E3),1X,L1,1X,I0)') &\n    '" + v50 + "', " + literal(n) +
              ", '-', value, lo, hi, inside, status\n";
  }
  return text + "end program drive\n";
}

std::string c_driver(const Json& description, const std::vector<Point>& points, const std::vector<double>& sizes) {
  std::string text =
      "#include <stdio.h>\n#include \"study1_correlations.h\"\nint main(void) {\n  double value, lo, hi;\n"
      "  int inside, status;\n";
  for (const auto& f : description.at("functions")) {
    const std::string p = f.at("p"), v50 = f.at("v50");
    for (const auto& point : points) {
      char call[512];
      std::snprintf(call, sizeof call,
                    "  value = %s(%.17e, %.17e, &lo, &hi, &inside, &status);\n"
                    "  printf(\"%s %.17e %.17e %%.17e %%.17e %%.17e %%d %%d\\n\", value, lo, hi, inside, status);\n",
                    p.c_str(), point.v, point.n, p.c_str(), point.v, point.n);
      text += call;
    }
    for (const double n : sizes) {
      char call[512];
      std::snprintf(call, sizeof call,
                    "  value = %s(%.17e, &lo, &hi, &inside, &status);\n"
                    "  printf(\"%s %.17e - %%.17e %%.17e %%.17e %%d %%d\\n\", value, lo, hi, inside, status);\n",
                    v50.c_str(), n, v50.c_str(), n);
      text += call;
    }
  }
  return text + "  return 0;\n}\n";
}

// Comma-separated, each to 17 significant digits: the service parses the same doubles.
std::string number_list(const std::vector<double>& values) {
  std::string text;
  for (const double value : values) {
    char number[40];
    std::snprintf(number, sizeof number, "%.17g", value);
    text += (text.empty() ? "" : ",") + std::string(number);
  }
  return text;
}

void check_close(double got, double expected) {
  if (expected == 0.0)
    CHECK(std::abs(got) <= 1e-300);
  else
    CHECK(std::abs(got - expected) <= kRelative * std::abs(expected));
}

// The service's fit table as rows: (wall 1/0, n, v) -> column -> value.
std::map<std::tuple<double, double, double>, std::map<std::string, double>> fit_rows(const Json& table) {
  std::map<std::tuple<double, double, double>, std::map<std::string, double>> rows;
  std::map<std::string, const Json*> columns;
  for (const auto& column : table.at("columns")) columns[column.at("name")] = &column.at("values");
  for (std::size_t r = 0; r < table.at("rows").get<std::size_t>(); ++r) {
    auto& row = rows[{columns.at("wall_adhesive")->at(r).get<double>(), columns.at("primaries")->at(r).get<double>(),
                      columns.at("impact_speed")->at(r).get<double>()}];
    for (const auto& [name, values] : columns) row[name] = values->at(r).is_null() ? NAN : values->at(r).get<double>();
  }
  return rows;
}

// Every function at every point equals the service's row (value, band, status, validity flag).
void check_against_table(const Evaluations& code, const Json& description, const std::vector<Point>& points,
                         const Json& table) {
  const auto rows = fit_rows(table);
  std::size_t compared = 0;
  for (const auto& f : description.at("functions")) {
    const double wall = f.at("group").at("/wall/adhesive").get<bool>() ? 1.0 : 0.0;
    const std::string outcome =
        f.at("outcome") == "break-up" ? "p_break_up" : "p_" + f.at("outcome").get<std::string>();
    for (const auto& point : points) {
      const auto& name = f.at("p").get<std::string>();
      INFO(name << " at v = " << point.v << ", n = " << point.n);
      const auto found = code.find(key(name, point.v, point.n));
      REQUIRE(found != code.end());
      const auto& row = rows.at({wall, point.n, point.v});
      CHECK(found->second.status == static_cast<int>(row.at(outcome + "_status")));
      check_close(found->second.value, row.at(outcome));
      check_close(found->second.lo, row.at(outcome + "_lo"));
      check_close(found->second.hi, row.at(outcome + "_hi"));
      CHECK(found->second.inside == (row.at("inside_validity") == 1.0));
      ++compared;
    }
  }
  CHECK(compared == description.at("functions").size() * points.size());
}

// v50 at the sizes run: the pooled fits' critical values as served (delta method).
void check_v50(const ServiceProcess& service, const Evaluations& code, const Json& description,
               const std::vector<double>& sizes) {
  std::size_t compared = 0;
  for (const auto& f : description.at("functions")) {
    if (f.at("status") != 0) continue;
    const Json fit = Json::parse(text_of(service, "/api/studies/1/correlations/" + f.at("fit").get<std::string>()));
    for (const auto& critical : fit.at("critical")) {
      if (critical.at("level") != 0.5) continue;
      const double n = critical.at("at").at("primaries");
      const auto found = code.find(key(f.at("v50"), n));
      REQUIRE(found != code.end());
      INFO(f.at("v50") << " at n = " << n);
      check_close(found->second.value, critical.at("estimate"));
      check_close(found->second.lo, critical.at("ci95")[0]);
      check_close(found->second.hi, critical.at("ci95")[1]);
      ++compared;
    }
  }
  CHECK(compared == 5 * sizes.size());  // every fitted function (stick only on the adhesive wall), each size
}

// The driver built in `scratch` by `compile` (which writes ./drive), run, and its values read back.
Evaluations built_and_run(const ScratchDirectory& scratch, const std::string& compile) {
  const auto built = run_command("cd " + scratch.path().string() + " && " + compile);
  INFO(built.text);
  REQUIRE(built.exit_code == 0);
  const auto output = run_command(scratch.file("drive"), true);
  REQUIRE(output.exit_code == 0);
  return parse_output(output.text);
}

}  // namespace

TEST_CASE("Correlations as code: gfortran and gcc programs agree with the service to 1e-12 at random points",
          "[service][export][code]") {
  ScratchDirectory scratch("correlation_code");
  {
    Store store(scratch.path() / "store.sqlite");
    REQUIRE(fill_pooled_wall_study(store) == 1);
  }
  ServiceProcess service(scratch.path());
  const std::string tables = "/api/studies/1/tables?kind=correlations&format=";
  const Json description = Json::parse(text_of(service, tables + "json"));
  std::ifstream schema_file(AEROBREAK_SOURCE_DIR "/schemas/correlation_code.schema.json");
  const JsonSchema schema(Json::parse(schema_file));
  INFO(describe(schema.validate(description)));
  CHECK(schema.validate(description).empty());
  REQUIRE(description.at("functions").size() == 6);  // stick, bounce, break-up x two walls
  std::map<int, int> statuses;
  for (const auto& f : description.at("functions")) ++statuses[f.at("status").get<int>()];
  CHECK(statuses == std::map<int, int>{{0, 5}, {2, 1}});  // nothing sticks on the wall without adhesion

  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point> points;
  std::vector<double> speeds, sizes;
  for (int i = 0; i < 5; ++i) speeds.push_back(0.01 * std::pow(30.0, unit(random)));  // inside 0.01-0.3
  for (int i = 0; i < 3; ++i) sizes.push_back(32.0 * std::pow(4.0, unit(random)));    // inside 32-128
  speeds.push_back(0.6), sizes.push_back(300.0);                                      // and outside both
  for (const double n : sizes)
    for (const double v : speeds) points.push_back({v, n});
  const Json table =
      Json::parse(text_of(service, "/api/studies/1/tables?kind=fit&format=json&speeds=" + number_list(speeds) +
                                       "&sizes=" + number_list(sizes)));
  const std::vector<double> run{32.0, 128.0};

  SECTION("the Fortran 90 module, compiled by gfortran") {
    const std::string gfortran = AEROBREAK_GFORTRAN;
    REQUIRE_FALSE(gfortran.empty());
    std::ofstream(scratch.file("study1_correlations.f90")) << text_of(service, tables + "fortran");
    std::ofstream(scratch.file("drive.f90")) << fortran_driver(description, points, run);
    const auto code =
        built_and_run(scratch, gfortran +
                                   " -std=f2008 -Wall -Werror -Wno-unused-dummy-argument "
                                   "-ffpe-trap=invalid,zero,overflow -o drive study1_correlations.f90 drive.f90");
    check_against_table(code, description, points, table);
    check_v50(service, code, description, run);
  }
  SECTION("the C header, compiled by gcc") {
    std::ofstream(scratch.file("study1_correlations.h")) << text_of(service, tables + "c");
    std::ofstream(scratch.file("drive.c")) << c_driver(description, points, run);
    const auto code = built_and_run(scratch, "gcc -std=c99 -pedantic -Wall -Wextra -Werror -o drive drive.c -lm");
    check_against_table(code, description, points, table);
    check_v50(service, code, description, run);
  }
  CHECK(service.kill(SIGTERM) == 0);
}

}  // namespace aerobreak::testing
