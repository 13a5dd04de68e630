// Correlation benchmark (docs/PERFORMANCE.md, "Correlations"); prints figures, asserts nothing.
//   correlation_bench [RESULTS] [STORE]
// 1. compute_correlations on a synthetic study of RESULTS (default 100,000) case outcomes: 20 speeds
//    x 5 cluster sizes x 5 gamma/k_n (500 grid points), outcomes from a logistic law, an energy per
//    contact and a retained fraction per case, re-entrained fragments for break-ups; best of three.
// 2. With STORE: the same study written into a new store file (one bulk transaction), then the
//    cache's first request (read, hash, fit, store) and a second one (served from the store).
//    tests/bench/correlation_bench.sh then serves that store and measures GET .../correlations with wrk.
#include <chrono>
#include <ctime>
#include <thread>
#include <cstdio>
#include <filesystem>
#include <string>

#include "orchestrator/fitting/correlation_set.hpp"
#include "orchestrator/app/study_fits.hpp"
#include "tests/fitting/synthetic_study.hpp"

namespace aerobreak {
namespace {

const std::vector<double> kSpeeds = synthetic::log_speeds(0.005, 0.5, 20);
const std::vector<double> kPrimaries{32, 64, 128, 256, 512};
const std::vector<double> kGammas{0.0003, 0.001, 0.003, 0.01, 0.03};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One case: v50 grows as gamma^0.4 N^-0.1 (a made-up law with the shape of the default study's).
CaseOutcome draw_case(std::size_t point, double speed, double primaries, double gamma, synthetic::Uniform& uniform) {
  const double v50 = 0.5 * std::pow(gamma, 0.4) * std::pow(primaries, -0.1);
  const synthetic::LogisticLaw law{v50, 3.0};
  CaseOutcome c;
  c.grid_point = point;
  c.primaries = static_cast<std::int64_t>(primaries);
  const double u = uniform();
  c.outcome = u < law.probability(speed)          ? ImpactOutcome::break_up
              : u < law.probability(speed) + 0.03 ? ImpactOutcome::bounce
                                                  : ImpactOutcome::stick;
  c.energy_per_contact = 3.0 * std::pow(speed / v50, 2.0) * (0.8 + 0.4 * uniform());
  c.retained_mass_fraction = c.outcome == ImpactOutcome::stick    ? 1.0
                             : c.outcome == ImpactOutcome::bounce ? 0.0
                                                                  : 0.2 + 0.6 * uniform();
  c.damage_ratio = 0.1 * uniform();
  c.small_strain_exceeded = speed > 4.0 * v50;
  if (c.outcome == ImpactOutcome::break_up)
    for (int k = 0; k < 6; ++k)
      c.reentrained_sizes.push_back(1 + static_cast<std::int64_t>(std::pow(uniform(), -0.8)) % 20);
  return c;
}

CaseOutcomeTable synthetic_study(std::size_t results) {
  CaseOutcomeTable table;
  table.axes = {"impact_speed", "primaries", "gamma_over_kn"};
  synthetic::Uniform uniform(2026);
  for (const double n : kPrimaries)
    for (const double gamma : kGammas)
      for (const double speed : kSpeeds)
        table.grid_points.push_back({{"impact_speed", speed}, {"primaries", n}, {"gamma_over_kn", gamma}});
  for (std::size_t i = 0; i < results; ++i) {
    const std::size_t point = i % table.grid_points.size();
    const auto& g = table.grid_points[point];
    table.cases.push_back(draw_case(point, g["impact_speed"], g["primaries"], g["gamma_over_kn"], uniform));
  }
  return table;
}

CorrelationRequest request() {
  return {"impact_speed", {{"primaries", true}, {"gamma_over_kn", true}}, {0.1, 0.5, 0.9}, "primaries"};
}

void time_fitting(const CaseOutcomeTable& table) {
  double best = 1e30, best_cpu = 1e30;
  std::size_t fits = 0;
  for (int run = 0; run < 3; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    const CorrelationSet set = compute_correlations(table, request(), {});
    best = std::min(best, seconds_since(start));
    best_cpu = std::min(best_cpu, static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    fits = set.logistic.size() + set.multinomial.size() + set.scaling.size() + set.retained_fraction.size() +
           set.fragment_sizes.size();
  }
  std::printf(
      "compute_correlations: %zu results, %zu grid points, %zu fits: %.3f s wall, %.3f s CPU on %u threads "
      "(best of 3)\n",
      table.cases.size(), table.grid_points.size(), fits, best, best_cpu, std::thread::hardware_concurrency());
}

StudySubmission submission_of(const CaseOutcomeTable& table) {
  StudySubmission study;
  study.hash = "correlation-bench";
  study.name = "correlation bench";
  study.document = {{"name", study.name},
                    {"axes",
                     {{"impact_speed", {{"values", kSpeeds}}},
                      {"primaries", {{"values", kPrimaries}}},
                      {"gamma_over_kn", {{"values", kGammas}}}}}};
  for (std::size_t i = 0; i < table.cases.size(); ++i) {
    StudySubmission::Case c;
    c.grid_point = table.grid_points[table.cases[i].grid_point];
    c.grid_key = c.grid_point.dump();
    c.replicate = static_cast<int>(i / table.grid_points.size());
    c.hash = std::to_string(i);
    c.document = nlohmann::ordered_json::object();
    study.cases.push_back(std::move(c));
  }
  return study;
}

// The results and fragments of every case, in one transaction (case ids are 1..n in table order).
void write_results(const std::filesystem::path& file, const CaseOutcomeTable& table) {
  SqliteDatabase db(file);
  SqliteTransaction transaction(db);
  db.execute("UPDATE cases SET status = 'done'");
  auto result = db.prepare(
      "INSERT INTO results (case_id, attempt, outcome, restitution, retained_mass_fraction, damage_ratio, "
      "energy_per_contact, small_strain_exceeded, document, committed_at) VALUES (?, 1, ?, 0.2, ?, ?, ?, ?, '{}', 0)");
  auto fragment = db.prepare("INSERT INTO fragments (case_id, rank, primaries, mass, on_wall) VALUES (?, ?, ?, ?, 0)");
  for (std::size_t i = 0; i < table.cases.size(); ++i) {
    const CaseOutcome& c = table.cases[i];
    const auto id = static_cast<std::int64_t>(i + 1);
    result.reset();
    result.bind_all(id, std::string(to_string(c.outcome)), *c.retained_mass_fraction, *c.damage_ratio,
                    *c.energy_per_contact, static_cast<std::int64_t>(c.small_strain_exceeded));
    result.run();
    for (std::size_t k = 0; k < c.reentrained_sizes.size(); ++k) {
      fragment.reset();
      fragment.bind_all(id, static_cast<std::int64_t>(k), c.reentrained_sizes[k],
                        static_cast<double>(c.reentrained_sizes[k]));
      fragment.run();
    }
  }
  transaction.commit();
}

int bench_store(const CaseOutcomeTable& table, const std::filesystem::path& file) {
  std::filesystem::remove(file);
  {
    Store store(file);
    store.submit_study(submission_of(table));
  }
  write_results(file, table);
  Store store(file);
  const StudyRecord study = *store.study(1);
  StudyFits cache(store);
  const CorrelationRequest ask = correlation_request(study, std::nullopt);
  auto start = std::chrono::steady_clock::now();
  const auto first = cache.current(study, ask);
  const double cold = seconds_since(start);
  start = std::chrono::steady_clock::now();
  cache.current(study, ask);
  std::printf(
      "store %s: first request (read, hash, fit, store) %.3f s, of which fitting %.3f s; "
      "second request (from the store) %.2f ms; summary %zu bytes\n",
      file.c_str(), cold, first->fit_seconds, 1e3 * seconds_since(start), first->summary.size());
  return 0;
}

}  // namespace
}  // namespace aerobreak

int main(int argc, char** argv) {
  using namespace aerobreak;
  const std::size_t results = argc > 1 ? std::stoul(argv[1]) : 100000;
  const CaseOutcomeTable table = synthetic_study(results);
  time_fitting(table);
  if (argc > 2) return bench_store(table, argv[2]);
  return 0;
}
