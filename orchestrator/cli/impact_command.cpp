#include "orchestrator/cli/impact_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/version.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_run.hpp"
#include "engine/io/h5md_writer.hpp"
#include "engine/io/xyz.hpp"
#include "orchestrator/cli/exit_codes.hpp"

namespace aerobreak {
namespace {

struct ImpactOptions {
  std::string case_file;
  std::string output = "-";
  std::string trajectory;
  std::string xyz;
  bool quiet = false;
  bool check = false;
  double progress_seconds = 2.0;
};

// Where a document goes: stdout for "-"; otherwise the folder is created and a temporary file
// beside the target opened at once, so that an unwritable path fails before a long run, and the
// document appears under its name only when it is complete (a rename), never half written.
class DocumentFile {
 public:
  explicit DocumentFile(std::string path) : path_(std::move(path)) {
    if (path_ == "-") return;
    const std::filesystem::path target(path_);
    if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
    partial_ = path_ + ".partial";
    out_.open(partial_);
    if (!out_) throw std::runtime_error("cannot write " + path_);
  }
  DocumentFile(const DocumentFile&) = delete;
  DocumentFile& operator=(const DocumentFile&) = delete;
  ~DocumentFile() {
    if (!partial_.empty() && !written_) std::filesystem::remove(partial_);
  }

  void write(const nlohmann::ordered_json& document) {
    if (path_ == "-") {
      std::cout << document.dump(2) << "\n";
      return;
    }
    out_ << document.dump(2) << "\n";
    out_.close();
    if (!out_) throw std::runtime_error("cannot write " + path_);
    std::filesystem::rename(partial_, path_);
    written_ = true;
  }

 private:
  std::string path_;
  std::string partial_;
  std::ofstream out_;
  bool written_ = false;
};

// Frames of the trajectory files the user asked for, with a few observables in the H5MD file.
class TrajectoryFiles {
 public:
  explicit TrajectoryFiles(const ImpactOptions& o) {
    if (!o.trajectory.empty()) h5md_.emplace(o.trajectory, version());
    if (!o.xyz.empty()) {
      xyz_.open(o.xyz);
      if (!xyz_) throw std::runtime_error("cannot write " + o.xyz);
    }
  }
  bool wanted() const { return h5md_.has_value() || xyz_.is_open(); }

  void frame(const Simulation& sim) {
    std::size_t pair_contacts = 0, wall_contacts = 0;
    sim.contacts().for_each([&](const ContactState& c) { ++(c.with_wall ? wall_contacts : pair_contacts); });
    if (h5md_) {
      h5md_->append(sim.particles(), sim.step_count(), sim.time());
      h5md_->append_observable("kinetic_energy", sim.step_count(), sim.time(), sim.energy().kinetic());
      h5md_->append_observable("contacts", sim.step_count(), sim.time(), static_cast<double>(pair_contacts));
      h5md_->append_observable("wall_contacts", sim.step_count(), sim.time(), static_cast<double>(wall_contacts));
    }
    if (xyz_.is_open()) {
      char comment[160];
      std::snprintf(comment, sizeof comment, "step=%lld time=%.9g contacts=%zu wall_contacts=%zu",
                    static_cast<long long>(sim.step_count()), sim.time(), pair_contacts, wall_contacts);
      write_xyz_frame(xyz_, sim.particles(), comment);
      xyz_.flush();
    }
  }

  void close() {
    if (h5md_) h5md_->close();
    if (xyz_.is_open()) xyz_.close();
  }

 private:
  std::optional<H5mdTrajectoryWriter> h5md_;
  std::ofstream xyz_;
};

void print_progress(const ImpactProgress& p) {
  std::fprintf(stderr,
               "impact: t = %.6g / %.6g tau (%4.1f%%)  %lld steps  %.3g steps/s  %.3g particle-steps/s  "
               "contacts %zu  wall %zu  fragments %zu  kinetic %.4g\n",
               p.time, p.time_limit, 100.0 * p.time / p.time_limit, static_cast<long long>(p.steps), p.steps_per_second,
               p.particle_steps_per_second, p.contacts, p.wall_contacts, p.fragments, p.kinetic_energy);
}

// Each line of `text` on stderr, after "impact: ".
void print_lines(const std::string& text) {
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    std::fprintf(stderr, "impact: %s\n", text.substr(begin, end - begin).c_str());
    begin = end + 1;
  }
}

int report_invalid_case(const ImpactOptions& o, const CaseError& e) {
  std::cerr << "aerobreak impact: invalid case " << o.case_file << ":\n";
  for (const auto& v : e.violations())
    std::cerr << "  " << (v.pointer.empty() ? std::string("(document)") : v.pointer) << ": " << v.message << "\n";
  return kExitInvalidInput;
}

int run_command(const ImpactOptions& o) {
  ImpactCase impact_case;
  try {
    impact_case = load_impact_case(o.case_file);
  } catch (const CaseError& e) {
    return report_invalid_case(o, e);
  }
  try {
    DocumentFile output(o.output);
    if (o.check) {
      output.write(impact_case.document);
      print_lines(describe_setup(prepare_impact(impact_case).result));
      return 0;
    }
    TrajectoryFiles files(o);
    ImpactRunOptions run;
    if (files.wanted()) run.snapshot = [&files](const Simulation& sim) { files.frame(sim); };
    if (!o.quiet) {
      run.progress = print_progress;
      run.progress_seconds = o.progress_seconds;
      run.log = [](const std::string& line) { std::fprintf(stderr, "impact: %s\n", line.c_str()); };
    }
    const ImpactResult result = run_impact(impact_case, run);
    files.close();
    if (!o.quiet)
      std::fprintf(stderr, "impact: %s after %.6g tau (%lld steps, %.3g s, %.3g s CPU, %.3g particle-steps/s): %s\n",
                   to_string(result.classification.outcome).c_str(), result.simulated_time,
                   static_cast<long long>(result.steps), result.wall_clock_seconds, result.cpu_seconds,
                   result.particle_steps_per_second, result.classification.reason.c_str());
    output.write(to_json(result));
  } catch (const CaseError& e) {
    // Found when the cluster is read (its primaries overlap beyond the contact laws' range).
    return report_invalid_case(o, e);
  } catch (const std::exception& e) {
    std::cerr << "aerobreak impact: " << o.case_file << ": " << e.what() << "\n";
    return kExitPartlyFailed;
  }
  return 0;
}

}  // namespace

void add_impact_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ImpactOptions>();
  auto* impact = app.add_subcommand(
      "impact", "Run one impact case from a case JSON file (schemas/case.schema.json) and write its result JSON");
  impact->add_option("case", options->case_file, "Case file (JSON, schemas/case.schema.json)")
      ->required()
      ->check(CLI::ExistingFile);
  impact->add_option("-o,--output", options->output, "Result file (schemas/result.schema.json); '-' is stdout")
      ->capture_default_str();
  impact->add_option("--trajectory", options->trajectory,
                     "Write an H5MD trajectory here (frames every /run/snapshot_interval, first and last always)");
  impact->add_option("--xyz", options->xyz, "Write an extended-XYZ trajectory here (same frames)");
  impact->add_flag("-q,--quiet", options->quiet, "No progress output on stderr");
  impact->add_option("--progress-seconds", options->progress_seconds, "Wall-clock seconds between progress lines")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  impact->add_flag("--check", options->check,
                   "Only validate the case, write it completed with its defaults, and print (stderr) the time "
                   "unit, time step, lambda and energy groups of its set-up (no run)");
  impact->callback([options, &exit_code] { exit_code = run_command(*options); });
}

}  // namespace aerobreak
