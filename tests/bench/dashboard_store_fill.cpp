// A benchmark input, not a test: fills a store with one study of 100,000 synthetic finished cases
// for tests/bench/web_bench.mjs (docs/PERFORMANCE.md, "Dashboard"). Axes: 25 impact speeds
// (0.003 to 0.3 d/tau, log), N = 16, 32, 64, 128, gamma/k_n = 0.001, 0.003, 0.01, 0.03, 0.1 and
// four frictions, 50 replicates: 2,000 grid points. Outcomes are drawn from a logistic curve in
// log speed around v50 = 0.02 (gamma/k_n / 0.001)^0.5 (N / 32)^0.1; a break-up leaves 2 to 9
// fragments. Each result has the outcome columns of the outcomes migration: N_c = N - 1 + N / 4
// initial contacts, energy per contact 1/2 N v^2 / (N_c 1e-4), a damage ratio that grows with the
// fragments, a crack on the wall for one stick in five above v50 / 2, the small-strain flag for
// half the impacts faster than 0.1; and a result document of `--result-document-bytes` (default
// 14,000: the mean of 640 results of the default study), since real documents, not the numbers,
// make a results row large. The study and its cases go through Store::submit_study; the results and
// fragments are written straight into their tables in one transaction (committing them one by one,
// with a sync each, would take minutes).
// Usage: dashboard_store_fill STORE.sqlite [--result-document-bytes B]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "orchestrator/store/store.hpp"

namespace {

using aerobreak::SqliteDatabase;
using aerobreak::SqliteStatement;
using Json = nlohmann::ordered_json;

constexpr int kReplicates = 50;

aerobreak::StudySubmission synthetic_study() {
  aerobreak::StudySubmission study;
  study.hash = "synthetic-dashboard-benchmark";
  study.name = "synthetic: 100,000 cases";
  study.description = "Synthetic results for the dashboard benchmark (tests/bench/dashboard_store_fill.cpp)";
  Json axes = Json::object();
  for (int i = 0; i < 25; ++i) axes["impact_speed"].push_back(0.003 * std::pow(100.0, i / 24.0));
  axes["primaries"] = {16, 32, 64, 128};
  axes["gamma_over_kn"] = {0.001, 0.003, 0.01, 0.03, 0.1};
  axes["/model/friction"] = {0.1, 0.3, 0.5, 0.7};
  study.document = {{"name", study.name}, {"axes", axes}};
  for (const auto& speed : axes["impact_speed"])
    for (const auto& n : axes["primaries"])
      for (const auto& gamma : axes["gamma_over_kn"])
        for (const auto& friction : axes["/model/friction"]) {
          const Json point{
              {"impact_speed", speed}, {"primaries", n}, {"gamma_over_kn", gamma}, {"/model/friction", friction}};
          for (int r = 0; r < kReplicates; ++r) {
            const std::string hash = point.dump() + "#" + std::to_string(r);
            study.cases.push_back({hash, Json{{"synthetic", hash}, {"cluster", {{"generator", {{"primaries", n}}}}}},
                                   point, point.dump(), r});
          }
        }
  return study;
}

struct Draw {
  std::string outcome;
  std::vector<int> fragments;  // sizes, largest first
  double v50 = 0.0;
};

Draw draw_outcome(const Json& point, std::mt19937_64& random) {
  const double speed = point["impact_speed"], gamma = point["gamma_over_kn"];
  const int n = point["primaries"];
  const double v50 = 0.02 * std::sqrt(gamma / 0.001) * std::pow(n / 32.0, 0.1);
  const double p_break = 1.0 / (1.0 + std::exp(-4.0 * std::log(speed / v50)));
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  if (uniform(random) >= p_break) return {uniform(random) < 0.1 ? "bounce" : "stick", {n}, v50};
  Draw draw{"break-up", {}, v50};
  int left = n;
  const int pieces = std::uniform_int_distribution<int>(2, 9)(random);
  for (int k = 1; k < pieces && left > 1; ++k) {
    const int size = std::uniform_int_distribution<int>(1, std::max(1, left / 2))(random);
    draw.fragments.push_back(size);
    left -= size;
  }
  draw.fragments.push_back(left);
  std::sort(draw.fragments.rbegin(), draw.fragments.rend());
  return draw;
}

// The outcome columns of one result (docs/IMPACT.md section 5), synthetic but consistent with the draw.
struct OutcomeColumns {
  std::int64_t initial_contacts;
  double energy_per_contact, damage_ratio;
  int fractured_on_wall, small_strain_exceeded;
};

OutcomeColumns outcome_columns(const Json& point, const Draw& draw, std::mt19937_64& random) {
  const int n = point["primaries"];
  const double speed = point["impact_speed"];
  const std::int64_t contacts = n - 1 + n / 4;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double broken =
      double(draw.fragments.size() - 1) + (draw.outcome == "break-up" ? uniform(random) * n / 8 : 0.0);
  return {contacts, 0.5 * n * speed * speed / (double(contacts) * 1e-4), std::min(1.0, broken / double(contacts)),
          draw.outcome == "stick" && speed > draw.v50 / 2 && uniform(random) < 0.2 ? 1 : 0,
          speed > 0.1 && uniform(random) < 0.5 ? 1 : 0};
}

void write_results(SqliteDatabase& db, std::size_t document_bytes) {
  std::mt19937_64 random(2026);
  std::normal_distribution<double> normal(0.0, 1.0);
  const std::string document = Json{{"synthetic", true}, {"padding", std::string(document_bytes, 'x')}}.dump();
  auto cases = db.prepare(
      "SELECT c.id, sc.grid_point FROM study_cases sc JOIN cases c ON c.id = sc.case_id ORDER BY sc.position");
  auto result = db.prepare(
      "INSERT INTO results (case_id, attempt, outcome, restitution, largest_fragment_share, fragment_count, "
      "retained_mass_fraction, reentrained_mass_fraction, impact_energy, wall_clock_seconds, data_file, document, "
      "committed_at, initial_contacts, energy_per_contact, damage_ratio, fractured_on_wall, small_strain_exceeded) "
      "VALUES (?, 1, ?, ?, ?, ?, ?, 1 - ?6, ?, 0.1, NULL, ?, 1.7e9, ?, ?, ?, ?, ?)");
  auto fragment = db.prepare(
      "INSERT INTO fragments (case_id, rank, primaries, mass, on_wall, normal_velocity, radius_of_gyration) "
      "VALUES (?, ?, ?, ?, ?, ?, NULL)");
  db.execute("BEGIN");
  while (cases.step()) {
    const auto id = cases.integer(0);
    const auto point = Json::parse(cases.text(1));
    const auto draw = draw_outcome(point, random);
    const int n = point["primaries"];
    const double on_wall = draw.outcome == "stick"    ? 1.0
                           : draw.outcome == "bounce" ? 0.0
                                                      : double(draw.fragments[0]) / n;
    const auto columns = outcome_columns(point, draw, random);
    result.reset();
    result.bind_all(id, draw.outcome, 0.1 * normal(random) + (draw.outcome == "bounce" ? 0.3 : 0.0),
                    double(draw.fragments[0]) / n, static_cast<std::int64_t>(draw.fragments.size()), on_wall,
                    0.5 * n * std::pow(double(point["impact_speed"]), 2), document, columns.initial_contacts,
                    columns.energy_per_contact, columns.damage_ratio, columns.fractured_on_wall,
                    columns.small_strain_exceeded);
    result.run();
    for (std::size_t rank = 0; rank < draw.fragments.size(); ++rank) {
      fragment.reset();
      fragment.bind_all(id, static_cast<int>(rank), draw.fragments[rank], double(draw.fragments[rank]),
                        draw.outcome == "stick" || (rank == 0 && draw.outcome == "break-up") ? 1 : 0, normal(random));
      fragment.run();
    }
  }
  db.execute("UPDATE cases SET status = 'done', attempts = 1, started_at = 1.7e9, finished_at = 1.7e9 + id * 0.01");
  db.execute("COMMIT");
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t document_bytes = 14000;
  if (argc == 4 && std::string(argv[2]) == "--result-document-bytes") document_bytes = std::stoul(argv[3]);
  if (argc != 2 && argc != 4) {
    std::fprintf(stderr, "usage: dashboard_store_fill STORE.sqlite (a new file) [--result-document-bytes B]\n");
    return 2;
  }
  {
    aerobreak::Store store(argv[1]);
    const auto receipt = store.submit_study(synthetic_study());
    std::printf("study %lld: %zu cases\n", static_cast<long long>(receipt.study_id), receipt.cases);
  }
  SqliteDatabase db(argv[1]);
  write_results(db, document_bytes);
  std::printf("results written\n");
  return 0;
}
