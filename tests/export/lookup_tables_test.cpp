// The lookup tables (docs/EXPORT.md) of a study in a real store file: every number checked against
// a hand computation from the fragments the results left (export_study.hpp), the sectional
// columns summing to 1, SI against the unit formulas, and the material rules; a study on two walls
// (a boolean axis) tabulated per wall, and the encoding of every kind of axis.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "orchestrator/app/study_results_json.hpp"
#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/fitting/proportion.hpp"
#include "orchestrator/study/field_units.hpp"
#include "tests/export/export_study.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

// The row whose columns have these values.
std::size_t row_of(const LookupTable& table, std::initializer_list<std::pair<const char*, double>> where) {
  for (std::size_t row = 0; row < table.rows(); ++row) {
    bool match = true;
    for (const auto& [name, value] : where)
      match = match && std::abs(table.find(name)->values[row] - value) <= 1e-12 * std::abs(value);
    if (match) return row;
  }
  FAIL("no such row");
  return 0;
}

double at(const LookupTable& table, const char* column, std::size_t row) {
  REQUIRE(table.find(column));
  return table.find(column)->values[row];
}

ExportMaterial material_with_gamma_over_kn(double gamma_over_kn) {
  ExportMaterial material;
  material.material = {1e10, 0.3, 1725.0, 0.0};
  material.diameter = 2e-8;
  const double k_n = material.material.youngs_modulus * material.diameter / (3.0 * (1.0 - 0.09));  // eq 7
  material.material.surface_energy = gamma_over_kn * k_n;
  return material;
}

// Every row of a sections table (a column of the matrix): to_wall + the to_section_k, each >= 0, sum to 1.
void check_columns_sum_to_one(const LookupTable& table) {
  const int sections = table.metadata.at("sections").at("count");
  for (std::size_t row = 0; row < table.rows(); ++row) {
    double sum = at(table, "to_wall", row);
    for (int k = 1; k <= sections; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "to_section_%02d", k);
      CHECK(at(table, name, row) >= 0.0);
      sum += at(table, name, row);
    }
    CHECK(sum == Approx(1.0).margin(1e-12));
  }
}

struct ExportFixture {
  ScratchDirectory directory{"lookup_tables"};
  Store store{directory.path() / "store.sqlite"};
  std::int64_t study = fill_export_study(store);
  LookupTable table(ExportRequest request) { return study_lookup_table(store, study, request); }
};

}  // namespace

TEST_CASE("Grid table: outcome counts, Wilson intervals and fragment moments from the results", "[export]") {
  ExportFixture fixture;
  const auto table = fixture.table({});
  REQUIRE(table.rows() == kSpeeds.size() * kGammas.size() * kSizes.size());
  // Speed 0.02, N = 8: replicate r loses r monomers: one stick, three break-ups.
  const auto row = row_of(table, {{"impact_speed", 0.02}, {"gamma_over_kn", 0.001}, {"primaries", 8}});
  const auto wilson = *wilson_interval(1, 4);
  CHECK(at(table, "results", row) == 4);
  CHECK(at(table, "p_stick", row) == 0.25);
  CHECK(at(table, "p_stick_lo", row) == Approx(wilson.lower).epsilon(1e-12));
  CHECK(at(table, "p_stick_hi", row) == Approx(wilson.upper).epsilon(1e-12));
  CHECK(at(table, "p_break_up", row) == 0.75);
  CHECK(at(table, "p_bounce", row) == 0.0);
  CHECK(at(table, "reentrained_m0", row) == Approx((0 + 1 + 2 + 3) / 4.0));
  CHECK(at(table, "reentrained_m1", row) == Approx((0 + 1 + 2 + 3) / 4.0));
  CHECK(at(table, "monomer_mass_fraction", row) == Approx(6.0 / 32.0));
  CHECK(at(table, "retained_mass_fraction", row) == Approx((8 + 7 + 6 + 5) / 32.0));
  CHECK(at(table, "d_ve", row) == Approx(2.0));
  CHECK(at(table, "d_mob", row) == Approx(std::pow(8.0, 1.0 / 2.16)));
  // lambda of eq 19 in the closed form of docs/MODEL.md 1.3: 5.7855 (gamma/k_n)^(5/3) / v^2.
  CHECK(at(table, "lambda", row) == Approx(5.7855 * std::pow(0.001, 5.0 / 3.0) / (0.02 * 0.02)).epsilon(1e-4));
  // Speed 0.05, N = 32: three break-ups (a dimer and two monomers leave) and one bounce.
  const auto fast = row_of(table, {{"impact_speed", 0.05}, {"gamma_over_kn", 0.01}, {"primaries", 32}});
  CHECK(at(table, "p_bounce", fast) == 0.25);
  CHECK(at(table, "reentrained_m2", fast) == Approx((3 * (4 + 1 + 1) + 31 * 31) / 4.0));
  CHECK(at(table, "reentrained_m3", fast) == Approx((3 * (8 + 1 + 1) + 31.0 * 31 * 31) / 4.0));
  // Restitution over the bounces only, with their count (the one bounce: 0.2; the break-ups' -0.3
  // left out); missing where nothing bounced.
  CHECK(at(table, "restitution", fast) == Approx(0.2).epsilon(1e-12));
  CHECK(at(table, "restitution_bounces", fast) == 1.0);
  CHECK(std::isnan(at(table, "restitution_sd", fast)));
  CHECK(std::isnan(at(table, "restitution", row)));
  CHECK(at(table, "restitution_bounces", row) == 0.0);
  CHECK_FALSE(table.find("fractal_dimension"));  // the ballistic generator has no target D_f: no column
}

TEST_CASE("Undetermined results: counted in n and p_undetermined, left out of the probabilities and the means",
          "[export][undetermined]") {
  // Speed 0.05, N = 8, gamma/k_n 0.001: replicates 0-2 break up (a dimer and two monomers leave,
  // retained 4/8), replicate 3 bounces; here replicate 3 ends undetermined instead, its last state
  // retaining 0.75 of the mass.
  ScratchDirectory directory{"lookup_tables_undetermined"};
  Store store{directory.path() / "store.sqlite"};
  const auto receipt = store.submit_study(export_submission());
  const auto job = store.start_job("export test", 1);
  const auto is_marked = [](const CaseLabel& label, const nlohmann::ordered_json& document) {
    return label.size == 8 && label.speed_index == 2 && label.replicate == 3 &&
           document.at("material").at("gamma_over_kn") == 0.001;
  };
  while (const auto claimed = store.claim_next_case(job)) {
    const auto label = case_label(claimed->document);
    auto result = result_of(fragments_of(label.size, label.speed_index, label.replicate), label.size);
    if (is_marked(label, claimed->document)) {
      result["outcome"]["class"] = "undetermined";
      result["outcome"]["retained_mass_fraction"] = 0.75;
      result["outcome"]["damage_ratio"] = 0.75;
    }
    REQUIRE(store.commit_result(claimed->case_id, claimed->attempt, result, "", 0.1));
  }
  const auto table = study_lookup_table(store, receipt.study_id, {});
  const auto row = row_of(table, {{"impact_speed", 0.05}, {"gamma_over_kn", 0.001}, {"primaries", 8}});
  CHECK(at(table, "results", row) == 4);
  CHECK(at(table, "p_undetermined", row) == 0.25);
  CHECK(at(table, "p_break_up", row) == 1.0);  // 3 of the 3 determined, not 3 of 4
  CHECK(at(table, "p_bounce", row) == 0.0);
  const auto wilson = *wilson_interval(3, 3);
  CHECK(at(table, "p_break_up_lo", row) == Approx(wilson.lower).epsilon(1e-12));
  CHECK(at(table, "retained_mass_fraction", row) == Approx(0.5).epsilon(1e-12));  // 4/8 thrice; 0.75 left out
  CHECK(at(table, "damage_ratio", row) == Approx(0.5).epsilon(1e-12));
  CHECK(at(table, "energy_per_contact", row) == Approx(1.0));  // every result's
  // The service's grid points (GET /api/studies/ID/grid and /outcomes) count the same way.
  const auto cells = store.grid_statistics(receipt.study_id);
  const auto found = std::find_if(cells.begin(), cells.end(), [](const GridPointStatistics& cell) {
    return cell.outcomes.grid_point.at("impact_speed") == 0.05 && cell.outcomes.grid_point.at("primaries") == 8 &&
           cell.outcomes.grid_point.at("gamma_over_kn") == 0.001;
  });
  REQUIRE(found != cells.end());
  const auto json = grid_point_outcomes_json(*found);
  CHECK(json["finished"] == 4);
  CHECK(json["outcomes"]["break-up"]["probability"] == 1.0);
  CHECK(json["outcomes"]["undetermined"]["probability"] == 0.25);
  CHECK(json["retained_mass_fraction"]["n"] == 3);
  CHECK(json["retained_mass_fraction"]["mean"].get<double>() == Approx(0.5).epsilon(1e-12));
  CHECK(json["energy_per_contact"]["n"] == 4);
}

TEST_CASE("The grid table of an adaptive search says what its rows are and which table to read", "[export][search]") {
  ScratchDirectory directory{"lookup_tables_search"};
  Store store{directory.path() / "store.sqlite"};
  auto grid_study = export_submission();
  auto search_study = export_submission();
  search_study.hash = std::string(64, 's');
  search_study.name = "search";
  search_study.document = {{"name", "search"},
                           {"search", {{"axis", "impact_speed"}, {"range", {{"from", 0.01}, {"to", 0.05}}}}}};
  const auto searched = fill_study(store, search_study, [](const nlohmann::ordered_json& document) {
    const auto label = case_label(document);
    return fragments_of(label.size, label.speed_index, label.replicate);
  });
  const auto gridded = fill_study(store, grid_study, [](const nlohmann::ordered_json& document) {
    const auto label = case_label(document);
    return fragments_of(label.size, label.speed_index, label.replicate);
  });
  const auto table = study_lookup_table(store, searched, {});
  REQUIRE(table.metadata.contains("search"));
  CHECK(table.metadata["search"]["axis"] == "impact_speed");
  CHECK(table.metadata["search"]["note"] == kSearchedGridNote);
  CHECK(table.rows() == kSpeeds.size() * kGammas.size() * kSizes.size());
  CHECK_FALSE(study_lookup_table(store, gridded, {}).metadata.contains("search"));
  // The .dat header of the searched study's grid table carries it, within its 80 columns.
  ExportRequest dat;
  dat.format = TableFormat::dat;
  const auto text = render_table(study_lookup_table(store, searched, dat), dat, searched).content;
  CHECK(text.find("\n# search.axis: impact_speed\n") != std::string::npos);
  CHECK(text.find("\n# search.note: an adaptive search") != std::string::npos);
}

TEST_CASE("Sections table: each column of the matrix sums to 1 and equals the hand computation", "[export]") {
  ExportFixture fixture;
  for (const double ratio : {2.0, 3.0, 1.5}) {
    ExportRequest request;
    request.kind = TableKind::sections;
    request.section_ratio = ratio;
    const auto table = fixture.table(request);
    REQUIRE(table.rows() == kSpeeds.size() * kGammas.size() * kSizes.size());
    const int sections = table.metadata.at("sections").at("count");
    CHECK(sections == 1 + static_cast<int>(std::floor(std::log(32.0) / std::log(ratio) + 1e-12)));
    check_columns_sum_to_one(table);
  }
  ExportRequest request;
  request.kind = TableKind::sections;
  const auto table = fixture.table(request);
  // Speed 0.05, N = 32 (source section 6 = [32, 64)): three impacts leave 28 on the wall and a
  // dimer (section 2) and two monomers (section 1) leave; one leaves 1 on the wall and 31 (section 5).
  const auto row = row_of(table, {{"impact_speed", 0.05}, {"gamma_over_kn", 0.001}, {"source_section", 6}});
  CHECK(at(table, "to_wall", row) == Approx(85.0 / 128.0));
  CHECK(at(table, "to_section_01", row) == Approx(6.0 / 128.0));
  CHECK(at(table, "to_section_02", row) == Approx(6.0 / 128.0));
  CHECK(at(table, "to_section_05", row) == Approx(31.0 / 128.0));
  CHECK(at(table, "to_section_06", row) == 0.0);
  CHECK(at(table, "p_break_up", row) == 0.75);
  CHECK(at(table, "source_d_ve_lower", row) == Approx(std::cbrt(32.0)));
}

namespace {

struct WallFixture {
  ScratchDirectory directory{"lookup_walls"};
  Store store{directory.path() / "store.sqlite"};
  std::int64_t study = fill_wall_study(store);
  LookupTable table(ExportRequest request) { return study_lookup_table(store, study, request); }
};

// The wall_adhesive column: an input, 1 = adhesive, 0 = without adhesion, half the rows each.
void check_wall_column(const LookupTable& table) {
  const auto* wall = table.find("wall_adhesive");
  REQUIRE(wall);
  CHECK(wall->role == ColumnRole::input);
  CHECK(wall->unit == "1");
  CHECK(wall->description.find("/wall/adhesive (1 = true, 0 = false)") != std::string::npos);
  CHECK(std::count(wall->values.begin(), wall->values.end(), 1.0) == static_cast<long>(table.rows() / 2));
  CHECK(std::count(wall->values.begin(), wall->values.end(), 0.0) == static_cast<long>(table.rows() / 2));
}

}  // namespace

TEST_CASE("Grid table of a study on two walls: one row per wall, each counted by hand", "[export][axes]") {
  WallFixture fixture;
  const auto table = fixture.table({});
  REQUIRE(table.rows() == kSpeeds.size() * kSizes.size() * 2);
  check_wall_column(table);
  // Speed 0.05, N = 32 on the adhesive wall (fragments_of): three break-ups leave 28 of 32 on the
  // wall, one bounce leaves 1.
  const auto adhesive = row_of(table, {{"impact_speed", 0.05}, {"primaries", 32}, {"wall_adhesive", 1}});
  CHECK(at(table, "p_break_up", adhesive) == 0.75);
  CHECK(at(table, "p_bounce", adhesive) == 0.25);
  CHECK(at(table, "retained_mass_fraction", adhesive) == Approx(85.0 / 128.0));
  CHECK(at(table, "reentrained_m0", adhesive) == Approx((3 * 3 + 1) / 4.0));
  // The same condition without adhesion: replicates 0 and 2 leave in two halves, 1 and 3 whole.
  const auto bare = row_of(table, {{"impact_speed", 0.05}, {"primaries", 32}, {"wall_adhesive", 0}});
  CHECK(at(table, "p_break_up", bare) == 0.5);
  CHECK(at(table, "p_bounce", bare) == 0.5);
  CHECK(at(table, "retained_mass_fraction", bare) == 0.0);
  CHECK(at(table, "reentrained_m0", bare) == Approx((2 + 1 + 2 + 1) / 4.0));
  // Speed 0.01: every cluster sticks to the adhesive wall and bounces off the other.
  CHECK(at(table, "p_stick", row_of(table, {{"impact_speed", 0.01}, {"primaries", 8}, {"wall_adhesive", 1}})) == 1.0);
  CHECK(at(table, "p_bounce", row_of(table, {{"impact_speed", 0.01}, {"primaries", 8}, {"wall_adhesive", 0}})) == 1.0);
}

TEST_CASE("Sections table of a study on two walls: one matrix per wall, columns summing to 1, counted by hand",
          "[export][axes]") {
  WallFixture fixture;
  ExportRequest request;
  request.kind = TableKind::sections;
  const auto table = fixture.table(request);
  REQUIRE(table.rows() == kSpeeds.size() * kSizes.size() * 2);
  check_wall_column(table);
  check_columns_sum_to_one(table);
  // Speed 0.05, source section 6 = [32, 64), adhesive wall: 85 of 128 primaries stay, 6 leave as
  // monomers, 6 as dimers, 31 in section 5.
  const auto adhesive = row_of(table, {{"impact_speed", 0.05}, {"source_section", 6}, {"wall_adhesive", 1}});
  CHECK(at(table, "to_wall", adhesive) == Approx(85.0 / 128.0));
  CHECK(at(table, "to_section_01", adhesive) == Approx(6.0 / 128.0));
  CHECK(at(table, "to_section_02", adhesive) == Approx(6.0 / 128.0));
  CHECK(at(table, "to_section_05", adhesive) == Approx(31.0 / 128.0));
  CHECK(at(table, "results", adhesive) == 4);
  // Without adhesion: nothing stays, half the mass leaves in halves of 16 (section 5), half whole.
  const auto bare = row_of(table, {{"impact_speed", 0.05}, {"source_section", 6}, {"wall_adhesive", 0}});
  CHECK(at(table, "to_wall", bare) == 0.0);
  CHECK(at(table, "to_section_05", bare) == Approx(0.5));
  CHECK(at(table, "to_section_06", bare) == Approx(0.5));
  CHECK(at(table, "p_break_up", bare) == 0.5);
  CHECK(at(table, "results", bare) == 4);
}

TEST_CASE("Axis columns: numbers as they are, booleans as 1/0, text as an index with its labels in the metadata",
          "[export][axes]") {
  const std::vector<nlohmann::ordered_json> points{
      {{"primaries", 8}, {"generator", "ballistic"}, {"/wall/adhesive", true}, {"/model/friction", 0.3}, {"/odd", 1}},
      {{"primaries", 8}, {"generator", "dlca"}, {"/wall/adhesive", false}, {"/model/friction", 0.5}, {"/odd", "x"}},
      {{"primaries", 8},
       {"generator", "ballistic"},
       {"/wall/adhesive", false},
       {"/model/friction", 0.3},
       {"/odd", true}}};
  std::vector<const nlohmann::ordered_json*> pointers;
  for (const auto& point : points) pointers.push_back(&point);
  const auto axes = axis_columns(pointers, {"primaries"}, false);
  REQUIRE(axes.size() == 4);
  const auto values = [&](std::size_t axis) {
    std::vector<double> column;
    for (const auto& point : points) column.push_back(axes[axis].value(point));
    return column;
  };
  CHECK(axes[0].name == "generator");
  CHECK(values(0) == std::vector<double>{0, 1, 0});
  CHECK(axes[1].name == "wall_adhesive");
  CHECK(values(1) == std::vector<double>{1, 0, 0});
  CHECK(axes[2].name == "model_friction");
  CHECK(values(2) == std::vector<double>{0.3, 0.5, 0.3});
  CHECK(axes[2].unit() == "1");  // a friction coefficient
  CHECK(axes[1].unit() == "1");  // a boolean
  // Every quantity with its unit: SI for a physical study's material, d, m, tau otherwise.
  CHECK(exported_axis_unit("/material/surface_energy", true) == "J/m^2");
  CHECK(exported_axis_unit("/material/surface_energy", false) == "m/tau^2");
  CHECK(exported_axis_unit("/model/rolling/critical_displacement", true) == "d");
  CHECK(exported_axis_unit("/impact/angle", false) == "deg");
  CHECK(exported_axis_unit("fractal_dimension", true) == "1");
  CHECK(exported_axis_unit("/somewhere/else", true) == "unknown");
  // The same table, as the study's units write it: no unit for a number without one, nor for a
  // physical-only field in a reduced case.
  CHECK(case_field_unit("/model/friction", true).empty());
  CHECK(case_field_unit("/material/surface_energy", false).empty());
  CHECK(case_field_unit("/material/surface_energy", true) == "J/m^2");
  CHECK(values(3) == std::vector<double>{0, 1, 2});  // mixed values: labels "1", "x", "true"
  nlohmann::ordered_json metadata = nlohmann::ordered_json::object();
  add_axis_labels(metadata, axes);
  CHECK(metadata.at("axis_labels").at("generator") == nlohmann::ordered_json::array({"ballistic", "dlca"}));
  CHECK(metadata.at("axis_labels").at("odd") == nlohmann::ordered_json::array({"1", "x", "true"}));
  CHECK_FALSE(metadata.at("axis_labels").contains("wall_adhesive"));
}

TEST_CASE("select=NAME:VALUE keeps the rows of one condition, an unknown column or no match is refused naming select",
          "[export][axes]") {
  WallFixture fixture;
  ExportRequest request;
  request.select = {{"wall_adhesive", 0}, {"primaries", 32}};
  const auto table = fixture.table(request);
  REQUIRE(table.rows() == kSpeeds.size());
  for (std::size_t row = 0; row < table.rows(); ++row) CHECK(at(table, "wall_adhesive", row) == 0.0);
  CHECK(at(table, "p_break_up", row_of(table, {{"impact_speed", 0.05}})) == 0.5);
  for (const auto& select :
       std::vector<std::pair<std::string, double>>{{"wall_colour", 1}, {"wall_adhesive", 2}, {"p_stick", 1}}) {
    request.select = {select};
    try {
      fixture.table(request);
      FAIL("select=" << select.first << " was served");
    } catch (const ExportError& error) {
      CHECK(error.status == 422);
      CHECK(error.field == "select");
    }
  }
}

TEST_CASE("SI columns for a material: speeds in m/s and sizes in m, checked by hand", "[export]") {
  ExportFixture fixture;
  ExportRequest request;
  request.material = material_with_gamma_over_kn(0.01);
  const auto table = fixture.table(request);
  REQUIRE(table.rows() == kSpeeds.size() * kSizes.size());  // the rows of gamma/k_n = 0.01 only
  // By hand: k_n = E d / (3 (1 - nu^2)) = 1e10 * 2e-8 / 2.73 = 73.2601 N/m (eq 7);
  // m = rho pi d^3 / 6 = 1725 pi 8e-24 / 6 = 7.2257e-21 kg; tau = sqrt(m / k_n) = 9.9313e-12 s;
  // d / tau = 2013.84 m/s.
  const double k_n = 1e10 * 2e-8 / 2.73;
  const double mass = 1725.0 * std::numbers::pi * 8e-24 / 6.0;
  const double speed_unit = 2e-8 / std::sqrt(mass / k_n);
  CHECK(speed_unit == Approx(2013.84).epsilon(1e-5));
  for (std::size_t row = 0; row < table.rows(); ++row) {
    CHECK(at(table, "gamma_over_kn", row) == 0.01);
    CHECK(at(table, "impact_speed_m_s", row) == Approx(at(table, "impact_speed", row) * speed_unit).epsilon(1e-12));
    CHECK(at(table, "d_ve_m", row) == Approx(2e-8 * std::cbrt(at(table, "primaries", row))).epsilon(1e-12));
    CHECK(at(table, "d_mob_m", row) == Approx(2e-8 * at(table, "d_mob", row)).epsilon(1e-12));
  }
  CHECK(table.find("impact_speed_m_s")->unit == "m/s");
  CHECK(table.find("d_ve_m")->unit == "m");
  CHECK(table.metadata.at("units") == "reduced and SI");
  // The diameters say what they were computed with: the material's d and density, k_a and D_alpha.
  const auto& diameters = table.metadata.at("diameters");
  CHECK(diameters.at("primary_diameter_m") == 2e-8);
  CHECK(diameters.at("primary_density_kg_m3") == 1725.0);
  CHECK_THAT(diameters.at("mobility").get<std::string>(), Catch::Contains("k_a = 1, D_alpha = 1.08"));
  CHECK_THAT(diameters.at("aerodynamic").get<std::string>(), Catch::Contains("rho_0 = 1000 kg/m^3"));
  // Without SI, the relations in d only.
  const auto reduced = fixture.table(ExportRequest{});
  CHECK(reduced.metadata.at("diameters").contains("mobility"));
  CHECK_FALSE(reduced.metadata.at("diameters").contains("primary_density_kg_m3"));
}

TEST_CASE(
    "A material outside the study's gamma/k_n range is refused, and one between two values is taken only when "
    "interpolated",
    "[export]") {
  ExportFixture fixture;
  ExportRequest request;
  for (const double outside : {0.02, 0.0005}) {
    request.material = material_with_gamma_over_kn(outside);
    try {
      fixture.table(request);
      FAIL("a material outside the range was accepted");
    } catch (const ExportError& error) {
      CHECK(error.status == 422);
      CHECK(error.field == "surface_energy");
      CHECK_THAT(error.what(), Catch::Contains("outside the study's range"));
    }
  }
  request.material = material_with_gamma_over_kn(0.003);
  CHECK_THROWS_AS(fixture.table(request), ExportError);
  request.interpolate_gamma = true;
  const auto table = fixture.table(request);
  REQUIRE(table.rows() == kSpeeds.size() * kSizes.size());
  ExportRequest plain;
  const auto grid = fixture.table(plain);
  const double w = std::log(3.0) / std::log(10.0);  // ln(0.003/0.001) / ln(0.01/0.001)
  for (std::size_t row = 0; row < table.rows(); ++row) {
    CHECK(at(table, "interpolated", row) == 1.0);
    CHECK(at(table, "gamma_over_kn", row) == Approx(0.003));
    const double speed = at(table, "impact_speed", row), size = at(table, "primaries", row);
    const auto low = row_of(grid, {{"impact_speed", speed}, {"gamma_over_kn", 0.001}, {"primaries", size}});
    const auto high = row_of(grid, {{"impact_speed", speed}, {"gamma_over_kn", 0.01}, {"primaries", size}});
    CHECK(at(table, "energy_per_contact", row) ==
          Approx((1 - w) * at(grid, "energy_per_contact", low) + w * at(grid, "energy_per_contact", high)));
    CHECK(at(table, "lambda", row) == Approx(5.7855 * std::pow(0.003, 5.0 / 3.0) / (speed * speed)).epsilon(1e-4));
  }
}

TEST_CASE("Export parameters: unknown, malformed or half a material are refused naming the parameter", "[export]") {
  const auto field_of = [](std::vector<std::pair<std::string, std::string>> parameters) {
    try {
      parse_export_request(parameters);
    } catch (const ExportError& error) {
      CHECK(error.status == 400);
      return error.field;
    }
    return std::string("(accepted)");
  };
  CHECK(field_of({{"format", "xlsx"}}) == "format");
  CHECK(field_of({{"kind", "everything"}}) == "kind");
  CHECK(field_of({{"colour", "red"}}) == "colour");
  CHECK(field_of({{"section_ratio", "1.0"}}) == "section_ratio");
  CHECK(field_of({{"youngs_modulus", "1e10"}}) == "poisson_ratio");
  CHECK(field_of({{"youngs_modulus", "-1"},
                  {"poisson_ratio", "0.3"},
                  {"density", "1"},
                  {"surface_energy", "1"},
                  {"diameter", "1"}}) == "youngs_modulus");
  CHECK(field_of({{"speeds", "1,x"}}) == "speeds");
  CHECK(field_of({{"select", "wall_adhesive"}}) == "select");
  CHECK(field_of({{"select", "Wall:1"}}) == "select");
  CHECK(field_of({{"select", "wall_adhesive:yes"}}) == "select");
  CHECK(field_of({{"select", "wall_adhesive:1,primaries:32"}}) == "(accepted)");
  CHECK(field_of({{"format", "csv"}, {"format", "dat"}}) == "format");
  CHECK(field_of({{"format", "melcor"}, {"kind", "sections"}, {"section_ratio", "4"}}) == "(accepted)");
}

TEST_CASE("A study without results cannot be tabulated (409)", "[export]") {
  ScratchDirectory directory("lookup_empty");
  Store store(directory.path() / "store.sqlite");
  const auto receipt = store.submit_study(export_submission());
  try {
    study_lookup_table(store, receipt.study_id, {});
    FAIL("an empty study was tabulated");
  } catch (const ExportError& error) {
    CHECK(error.status == 409);
    CHECK(error.field == "study");
  }
}

}  // namespace aerobreak::testing
