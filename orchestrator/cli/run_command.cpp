#include "orchestrator/cli/run_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "orchestrator/app/study_fits.hpp"
#include "orchestrator/app/study_results_json.hpp"
#include "orchestrator/app/study_submission.hpp"
#include "orchestrator/cli/exit_codes.hpp"
#include "orchestrator/cli/export_command.hpp"
#include "orchestrator/cli/orchestrator_options.hpp"
#include "orchestrator/cli/correlation_table.hpp"
#include "orchestrator/cli/outcome_table.hpp"
#include "orchestrator/cli/search_table.hpp"
#include "orchestrator/service/service.hpp"
#include "orchestrator/study/field_units.hpp"
#include "orchestrator/study/study_units.hpp"

namespace aerobreak {
namespace {

struct RunOptions {
  std::string study_file;
  OrchestratorOptions orchestrator;
  int port = 8080;
  bool keep_serving = false;
  bool recompute_data_files = false;
};

// ", 3 computed again: data file lost or damaged", or the advice when lost files were not asked for.
std::string lost_files_text(const SubmissionReceipt& receipt) {
  if (receipt.recomputed)
    return ", " + std::to_string(receipt.recomputed) + " computed again: data file lost or damaged";
  if (!receipt.data_files_lost) return {};
  return ", " + std::to_string(receipt.data_files_lost) +
         " with a data file lost or damaged (their results are kept; --recompute-data-files computes the files again)";
}

std::string duration_text(double seconds) {
  char text[32];
  if (seconds < 90.0)
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 5400.0)
    std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
  else
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
  return text;
}

std::string progress_line(const StudyProgress& progress) {
  const std::size_t finished = progress.by_status.at("done") + progress.by_status.at("failed");
  const std::size_t countable = progress.total - progress.by_status.at("cancelled");
  constexpr int kWidth = 30;
  const int filled = countable ? static_cast<int>(kWidth * finished / countable) : kWidth;
  std::ostringstream line;
  line << "[" << std::string(filled, '#') << std::string(kWidth - filled, '-') << "] " << finished << "/" << countable
       << " finished (" << progress.by_status.at("failed") << " failed, " << progress.by_status.at("running")
       << " running)";
  if (progress.cases_per_hour > 0.0) line << ", " << std::lround(progress.cases_per_hour) << " cases/h";
  if (progress.seconds_left && !progress.complete) line << ", ~" << duration_text(*progress.seconds_left) << " left";
  return line.str();
}

// Redraws one line on a terminal; elsewhere (CI logs, pipes) prints a line when the count changes,
// at most every 10 s.
class ProgressBar {
 public:
  ProgressBar() : terminal_(::isatty(STDERR_FILENO)) {}
  void show(const StudyProgress& progress) {
    const std::string line = progress_line(progress);
    const std::size_t finished = progress.by_status.at("done") + progress.by_status.at("failed");
    const auto now = std::chrono::steady_clock::now();
    if (terminal_) {
      std::cerr << "\r" << line << "\033[K" << std::flush;
    } else if (progress.complete || (finished != last_finished_ && now - last_line_ > std::chrono::seconds(10))) {
      std::cerr << line << "\n";
      last_line_ = now;
      last_finished_ = finished;
    }
  }
  void finish() {
    if (terminal_) std::cerr << "\n";
  }

 private:
  bool terminal_;
  std::size_t last_finished_ = static_cast<std::size_t>(-1);
  std::chrono::steady_clock::time_point last_line_{};
};

std::unique_ptr<Service> start_service(Store& store, Scheduler& scheduler, ServiceOptions options) {
  const int port = options.port;
  auto service = std::make_unique<Service>(store, &scheduler, options);
  try {
    service->start();
  } catch (const std::runtime_error&) {
    if (port == 0) throw;
    std::cerr << "aerobreak run: port " << port << " is taken; serving on a free port instead\n";
    options.port = 0;
    service = std::make_unique<Service>(store, &scheduler, options);
    service->start();
  }
  return service;
}

void print_failures(Store& store, std::int64_t study_id) {
  const auto failed = store.cases(study_id, CaseStatus::failed, {5, 0});
  if (failed.total == 0) return;
  std::cout << "\n" << failed.total << " case(s) failed; the first:\n";
  for (const auto& record : failed.items)
    std::cout << "  case " << record.id << " " << record.grid_point.dump() << " replicate " << record.replicate << ": "
              << record.error.value_or("(no error text)") << "\n";
}

// The study's lookup tables for system codes (docs/EXPORT.md), next to the store.
void print_tables(Store& store, StudyFits& fits, std::int64_t study_id) {
  auto directory = store.file();
  directory.replace_extension(".tables");
  try {
    const auto files = write_default_tables(store, fits, study_id, directory);
    std::cout << "\nLookup tables for system codes (docs/EXPORT.md) in " << directory.string() << "/:\n";
    for (const auto& file : files) std::cout << "  " << file.filename().string() << "\n";
  } catch (const std::exception& error) {
    std::cout << "\nNo lookup tables: " << error.what() << "\n";
  }
}

// The critical speeds of the study's fits (fitted and stored now: the tables and the service then
// read them from the store).
void print_critical_speeds(Store& store, StudyFits& fits, std::int64_t study_id) {
  const auto study = store.study(study_id);
  try {
    const auto set = fits.current(*study, correlation_request(*study, std::nullopt));
    std::cout << "\nCritical speeds in " << speed_unit_label(study_unit_system(study->document))
              << ": logistic fits of P in log impact speed, per group (docs/CORRELATIONS.md)\n\n"
              << format_critical_table(nlohmann::ordered_json::parse(set->summary), "impact_speed",
                                       study_unit_system(study->document))
              << "\n"
              << critical_table_legend();
  } catch (const CorrelationRequestError& error) {
    std::cout << "\nNo critical speeds: " << error.what() << "\n";
  }
}

// The service lives as long as the command: its address, printed at the start, is dead from now on.
void print_no_longer_served(const std::string& url, const std::filesystem::path& store_file) {
  std::cerr << "aerobreak run: the study is over and " << url << " is no longer served. To see the page, the API or "
            << "the tables again: aerobreak serve --store " << store_file.string()
            << " (then http://127.0.0.1:8080/), or run with --keep-serving next time.\n";
}

int run(RunOptions options) {
  ShutdownSignals signals;
  Study study;
  try {
    study = load_study(options.study_file);
  } catch (const StudyError& error) {
    std::cerr << "aerobreak run: " << options.study_file << " is not a valid study:\n";
    for (const auto& v : error.violations())
      std::cerr << "  " << (v.pointer.empty() ? std::string("(document)") : v.pointer) << ": " << v.message << "\n";
    return kExitInvalidInput;
  }
  if (options.orchestrator.store.empty())
    options.orchestrator.store = "runs/" + std::filesystem::path(options.study_file).stem().stem().string() + ".sqlite";

  const auto data_directory = options.orchestrator.data_directory();
  Store store(options.orchestrator.store, Store::Access::orchestrator, data_directory);
  const auto log = line_log(data_directory / "orchestrator.log");
  Scheduler scheduler(store, options.orchestrator.scheduler_options(log));
  DataFileChecker checker;
  const auto receipt = submit_study(study, store, checker, options.recompute_data_files);
  ServiceOptions service_options = options.orchestrator.service_options();
  service_options.port = options.port;
  service_options.access_log = log;
  const auto service = start_service(store, scheduler, service_options);
  scheduler.start();

  const std::string study_url = service->url() + "/api/studies/" + std::to_string(receipt.study_id);
  std::cerr << "aerobreak run: study '" << study.name << "': " << receipt.cases << " cases (" << receipt.already_done
            << " already done" << lost_files_text(receipt) << "), store " << store.file().string() << "\n"
            << "aerobreak run: workers: " << scheduler.status().launcher_command << "\n"
            << "aerobreak run: open " << service->url() << "/?study=" << receipt.study_id
            << " in a browser while the study runs (API: " << study_url << ")\n";

  const auto started = std::chrono::steady_clock::now();
  ProgressBar bar;
  StudyProgress progress;
  for (;;) {
    progress = *store.progress(receipt.study_id);
    bar.show(progress);
    if (progress.complete) break;
    if (signals.wait_for(std::chrono::milliseconds(500)) != 0) {
      bar.finish();
      std::cerr << "aerobreak run: interrupted; finished cases are kept: run the same command again to go on\n";
      service->stop();
      scheduler.stop();
      return kExitInterrupted;
    }
  }
  bar.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::cout << "Study '" << study.name << "' (" << study_url << ")\n\n";
  // A search's outcome table has a row per value it placed: its groups' crossings say more.
  if (study.search)
    std::cout << format_search_table(search_groups_json(store.search_groups(receipt.study_id, false)),
                                     study.search->axis,
                                     study_axis_unit(study.search->axis, study_unit_system(study.document)));
  else
    std::cout << format_outcome_table(outcome_table_json(store.grid_statistics(receipt.study_id)),
                                      study_unit_system(study.document));
  StudyFits fits(store);  // fitted once, for the critical speeds, the fit table and the code
  print_critical_speeds(store, fits, receipt.study_id);
  print_failures(store, receipt.study_id);
  print_tables(store, fits, receipt.study_id);
  std::cout << "\n"
            << progress.by_status.at("done") << " done, " << progress.by_status.at("failed") << " failed in "
            << duration_text(seconds) << "; store " << store.file().string() << "\n";
  scheduler.stop();
  if (options.keep_serving) {
    std::cerr << "aerobreak run: serving " << service->url() << " until Ctrl-C\n";
    signals.wait();
  }
  service->stop();
  if (!options.keep_serving) print_no_longer_served(service->url(), store.file());
  return progress.by_status.at("failed") > 0 ? kExitPartlyFailed : kExitDone;
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RunOptions>();
  auto* command = app.add_subcommand("run", "Run a study to completion locally and print the outcome table");
  command->add_option("study", options->study_file, "Study file (schemas/study.schema.json)")
      ->required()
      ->check(CLI::ExistingFile);
  options->orchestrator.add_to(*command);
  command->get_option("--store")->description("SQLite store file [default: runs/STUDY.sqlite]");
  command->add_option("--port", options->port, "Loopback port of the service while the study runs (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  command->add_flag("--keep-serving", options->keep_serving,
                    "Keep the service up after the study finished, until Ctrl-C");
  command->add_flag("--recompute-data-files", options->recompute_data_files,
                    "Compute again the done cases whose HDF5 data file is missing or damaged (without it they are "
                    "reported, and their results kept and served)");
  command->callback([options, &exit_code] {
    try {
      exit_code = run(*options);
    } catch (const std::exception& error) {
      std::cerr << "aerobreak run: " << error.what() << "\n";
      exit_code = kExitError;
    }
  });
}

}  // namespace aerobreak
