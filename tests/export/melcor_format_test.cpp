// MELCOR tabular functions (docs/EXPORT.md, "MELCOR") read back by the grammar of the TF input:
// TF_INPUT, then per function TF_ID 'name' scale and TF_TAB n with n records "i x y", x ascending,
// no missing value. Every outcome's probability and its interval ends, the share undetermined, the
// restitution and the retained mass are tabulated; the names are unique across quantities,
// conditions, table kinds and studies and follow the documented scheme; the speed ranges are in
// the unit of x.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "orchestrator/export/lookup_tables.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/app/study_fits.hpp"
#include "orchestrator/fitting/correlation_set.hpp"
#include "tests/export/finite_number.hpp"
#include "tests/export/pooled_size_study.hpp"
#include "tests/support/scratch_directory.hpp"

namespace aerobreak::testing {
namespace {

struct TabularFunction {
  std::string name;
  std::vector<double> x, y;
};

struct MelcorDeck {
  std::vector<TabularFunction> functions;
  std::map<std::string, std::string> conditions;  // number -> the legend's text
  std::vector<std::string> comments;
};

// The TF input grammar; '!' starts a comment (kept apart for the legend and the ranges).
MelcorDeck parse(const std::string& text) {
  MelcorDeck deck;
  std::vector<std::string> words;
  std::istringstream lines(text);
  const std::regex legend(R"(^! condition (\d{3}): (.*)$)");
  for (std::string line; std::getline(lines, line);) {
    const auto bang = line.find('!');
    if (bang != std::string::npos) {
      deck.comments.push_back(line.substr(bang));
      std::smatch match;
      if (std::regex_match(deck.comments.back(), match, legend)) deck.conditions[match[1]] = match[2];
    }
    std::istringstream in(line.substr(0, bang));
    for (std::string word; in >> word;) words.push_back(word);
  }
  REQUIRE(words.at(0) == "TF_INPUT");
  for (std::size_t i = 1; i < words.size();) {
    REQUIRE(words.at(i) == "TF_ID");
    const std::string quoted = words.at(i + 1);
    REQUIRE((quoted.size() > 2 && quoted.front() == '\'' && quoted.back() == '\''));
    TabularFunction function{quoted.substr(1, quoted.size() - 2), {}, {}};
    CHECK(finite_number(words.at(i + 2)) == 1.0);
    REQUIRE(words.at(i + 3) == "TF_TAB");
    const int n = std::stoi(words.at(i + 4));
    REQUIRE(n >= 1);
    i += 5;
    for (int k = 1; k <= n; ++k, i += 3) {
      CHECK(std::stoi(words.at(i)) == k);
      function.x.push_back(finite_number(words.at(i + 1)));
      function.y.push_back(finite_number(words.at(i + 2)));
      if (k > 1) CHECK(function.x[k - 1] > function.x[k - 2]);
    }
    deck.functions.push_back(std::move(function));
  }
  return deck;
}

// S<study><G|F|S><four-letter quantity><_|L|U><three-digit condition>.
const std::regex kName(R"(S(\d+)([GFMVAS])(PSTK|PBNC|PBRK|PUND|REST|RETN|WALL|TS\d\d)([_LU])(\d{3}))");

struct Stores {
  ScratchDirectory directory{"melcor_format"};
  Store store{directory.path() / "store.sqlite"};
  std::int64_t walls = fill_wall_study(store);
  std::int64_t gammas = fill_export_study(store);
  LookupTable table(std::int64_t study, TableKind kind) {
    ExportRequest request;
    request.kind = kind;
    return study_lookup_table(store, study, request);
  }
};

}  // namespace

TEST_CASE("MELCOR: every outcome with its interval, the restitution and the retained mass, per wall and size",
          "[export][melcor]") {
  Stores stores;
  const auto table = stores.table(stores.walls, TableKind::grid);
  const auto deck = parse(melcor_text(table));
  REQUIRE(deck.conditions.size() == 4);  // 2 sizes x 2 walls
  std::size_t adhesive = 0;
  for (const auto& [number, text] : deck.conditions)
    adhesive += text.find("wall_adhesive = " + number_text(1.0)) != std::string::npos;
  CHECK(adhesive == 2);
  std::map<std::string, std::size_t> per_quantity;
  std::set<std::string> names;
  for (const auto& function : deck.functions) {
    std::smatch match;
    REQUIRE(std::regex_match(function.name, match, kName));
    CHECK(function.name.size() <= kMelcorNameLength);
    CHECK(std::stoll(match[1]) == stores.walls);
    CHECK(match[2] == "G");
    CHECK(deck.conditions.count(match[5]) == 1);
    CHECK(names.insert(function.name).second);
    ++per_quantity[std::string(match[3]) + std::string(match[4])];
    for (const double y : function.y) CHECK((y >= -1.0 && y <= 1.0));
  }
  // Every probability and its interval ends, per condition; the retained mass; the restitution where
  // something bounced: not N = 8 on the adhesive wall (7 of 8 primaries leaving is below the 0.9 share).
  for (const char* quantity :
       {"PSTK_", "PSTKL", "PSTKU", "PBNC_", "PBNCL", "PBNCU", "PBRK_", "PBRKL", "PBRKU", "PUND_", "RETN_"}) {
    INFO(quantity);
    CHECK(per_quantity[quantity] == 4);
  }
  CHECK(per_quantity["REST_"] == 3);
  // Each function's values are the table's (10 digits): P(break-up) of condition 001 and its interval.
  const auto& p = table.find("p_break_up")->values;
  for (const auto& function : deck.functions)
    if (function.name.ends_with("PBRK_001"))
      for (std::size_t k = 0; k < function.x.size(); ++k)
        CHECK(std::find_if(p.begin(), p.end(), [&](double v) {
                return std::abs(v - function.y[k]) <= 5e-10 * std::max(1.0, v);
              }) != p.end());
}

TEST_CASE("MELCOR: names are unique across quantities, conditions, table kinds and studies", "[export][melcor]") {
  Stores stores;
  std::vector<std::pair<LookupTable, std::string>> tables;  // each with the table letter its names must carry
  for (const auto study : {stores.walls, stores.gammas}) {
    tables.emplace_back(stores.table(study, TableKind::grid), "G");
    tables.emplace_back(stores.table(study, TableKind::sections), "S");
  }
  // The fit table at sizes and at mobility diameters, as aerobreak run writes both, of a third study.
  const auto pooled = fill_pooled_wall_study(stores.store);
  const auto fits = study_correlations(stores.store, *stores.store.study(pooled),
                                       correlation_request(*stores.store.study(pooled), std::nullopt));
  ExportRequest at_sizes, at_diameters;
  at_sizes.kind = at_diameters.kind = TableKind::fit;
  at_diameters.diameters = {5.0, 8.0};  // in d: N = 32.3 and 89
  tables.emplace_back(study_lookup_table(stores.store, pooled, at_sizes, &fits), "F");
  tables.emplace_back(study_lookup_table(stores.store, pooled, at_diameters, &fits), "M");
  std::set<std::string> names;
  std::size_t functions = 0;
  for (const auto& [table, letter] : tables) {
    const auto deck = parse(melcor_text(table));
    for (const auto& function : deck.functions) {
      names.insert(function.name);
      ++functions;
      std::smatch match;
      REQUIRE(std::regex_match(function.name, match, kName));
      CHECK(match[2] == letter);
    }
  }
  CHECK(functions > 100);
  CHECK(names.size() == functions);
}

TEST_CASE("MELCOR: ranges in the unit of x (m/s with SI), in the header and above each function", "[export][melcor]") {
  Stores stores;
  ExportRequest request;
  request.material = ExportMaterial{{1e10, 0.3, 1725.0, 0.001 * 1e10 * 2e-8 / 2.73}, 2e-8};
  const auto table = study_lookup_table(stores.store, stores.gammas, request);
  const double unit = table.metadata.at("si_units").at("d_per_tau_m_s");
  const auto text = melcor_text(table);
  const auto deck = parse(text);
  const auto validity = table.metadata.at("validity");
  CHECK(validity.at("impact_speed_m_s")[0].get<double>() == Approx(0.01 * unit).epsilon(1e-12));
  CHECK(validity.at("impact_speed_m_s")[1].get<double>() == Approx(0.05 * unit).epsilon(1e-12));
  CHECK(text.find("! validity.impact_speed_m_s: [") != std::string::npos);
  CHECK(text.find("! x: impact speed [m/s]") != std::string::npos);
  for (const auto& function : deck.functions) {
    INFO(function.name);
    const std::string range = "from " + number_text(function.x.front()) + " to " + number_text(function.x.back());
    CHECK(std::any_of(deck.comments.begin(), deck.comments.end(), [&](const std::string& comment) {
      return comment.find("! " + function.name + ": ") == 0 && comment.find("[m/s] " + range) != std::string::npos;
    }));
    CHECK(function.x.back() <= 0.05 * unit * (1 + 1e-9));
  }
}

}  // namespace aerobreak::testing
