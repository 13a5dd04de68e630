#include "orchestrator/cli/cluster_command.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/ensemble_fit.hpp"
#include "engine/impact/cluster_generation.hpp"
#include "engine/io/cluster_files.hpp"
#include "engine/io/xyz.hpp"
#include "orchestrator/cli/exit_codes.hpp"

namespace aerobreak {
namespace {

using json = nlohmann::ordered_json;  // keys in the order written, for readable output

constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();

// ---- reporting -------------------------------------------------------------------------------

// Reports a failure of `aerobreak cluster <verb>` on stderr and ends the program with status 1
// (CLI11 returns a RuntimeError's exit code without printing anything itself).
[[noreturn]] void fail_command(const std::string& verb, const std::string& message) {
  std::cerr << "aerobreak cluster " << verb << ": error: " << message << "\n";
  throw CLI::RuntimeError(kExitError);
}

template <class Action>
void run_reporting_errors(const std::string& verb, Action action) {
  try {
    action();
  } catch (const CLI::Error&) {
    throw;
  } catch (const std::exception& error) {
    fail_command(verb, error.what());
  }
}

std::string format_number(double value, int significant_digits = 4) {
  if (!std::isfinite(value)) return "n/a";
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.*g", significant_digits, value);
  return text.data();
}

// ---- generate --------------------------------------------------------------------------------

struct GenerateOptions {
  std::string generator = "ballistic";
  std::int64_t primaries = 0;
  std::int64_t count = 1;
  std::uint64_t seed = 1;
  double diameter = 1.0;
  double geometric_standard_deviation = 1.0;
  double fractal_dimension = kNotGiven;
  double prefactor = kNotGiven;
  bool sintering = true;
  bool sintering_given = false;
  bool relax = true;
  double gamma_over_kn = 0.001;
  double poisson_ratio = 0.3;
  std::string output;  // a library if it ends in .h5 or .hdf5, an XYZ file otherwise
  std::string name_prefix;
  std::string xyz;
  bool overwrite = false;

  bool to_library() const;
  std::string xyz_file() const { return xyz.empty() ? output : xyz; }
};

bool GenerateOptions::to_library() const { return xyz.empty() && names_cluster_library(output); }

// The registry's request (engine/impact/cluster_generators.hpp) for cluster `seed`.
GeneratorRequest request_for(const GenerateOptions& o, std::uint64_t seed) {
  GeneratorRequest r;
  const ClusterGenerator* generator = find_cluster_generator(o.generator);
  r.method = generator ? std::string(generator->name) : o.generator;
  r.primaries = static_cast<std::size_t>(std::max<std::int64_t>(o.primaries, 0));
  r.seed = seed;
  r.geometric_mean_diameter = o.diameter;
  r.geometric_standard_deviation = o.geometric_standard_deviation;
  r.fractal_dimension = o.fractal_dimension;
  r.prefactor = o.prefactor;
  r.sintering = o.sintering;
  return r;
}

// The generator-specific fields given on the command line, as the registry names them.
std::vector<std::string> given_fields(const GenerateOptions& o) {
  std::vector<std::string> given;
  if (!std::isnan(o.fractal_dimension)) given.emplace_back("fractal_dimension");
  if (!std::isnan(o.prefactor)) given.emplace_back("prefactor");
  if (o.sintering_given) given.emplace_back("sintering");
  return given;
}

// The option that sets a field of the registry's request.
std::string option_of(const std::string& field) {
  static const std::array<std::pair<std::string_view, std::string_view>, 7> options{{
      {"method", "--generator"},
      {"primaries", "--primaries"},
      {"geometric_mean_diameter", "--diameter"},
      {"geometric_standard_deviation", "--gsd"},
      {"fractal_dimension", "--df"},
      {"prefactor", "--kf"},
      {"sintering", "--sintering"},
  }};
  for (const auto& [name, option] : options)
    if (name == field) return std::string(option);
  return field;
}

void check_generation(const GenerateOptions& o) {
  if (o.primaries < 1) throw std::runtime_error("--primaries must be at least 1, got " + std::to_string(o.primaries));
  const std::vector<GeneratorViolation> wrong = check_generator_request(request_for(o, 0), given_fields(o));
  if (!wrong.empty()) {
    const GeneratorViolation& first = wrong.front();
    const bool own = first.field == "method";
    throw std::runtime_error(own ? first.message : option_of(first.field) + " " + first.message);
  }
}

void check_output(const GenerateOptions& o) {
  if (o.count < 1) throw std::runtime_error("--count must be at least 1, got " + std::to_string(o.count));
  if (o.relax && (!(o.gamma_over_kn > 0.0) || !std::isfinite(o.gamma_over_kn)))
    throw std::runtime_error("--gamma-over-kn must be positive");
  if (o.relax && !(o.poisson_ratio >= 0.0 && o.poisson_ratio < 0.5))
    throw std::runtime_error("--poisson must lie in [0, 0.5)");
  if (o.output.empty() == o.xyz.empty())
    throw std::runtime_error(
        "give either --output FILE (.h5 or .hdf5: a cluster library; otherwise XYZ) or --xyz FILE");
  if (!o.to_library() && o.count != 1)
    throw std::runtime_error("an XYZ file holds one cluster; use --output FILE.h5 for --count " +
                             std::to_string(o.count));
  if (!o.to_library() && (!o.name_prefix.empty() || o.overwrite))
    throw std::runtime_error("--name and --overwrite apply to a cluster library (--output FILE.h5)");
}

// Names "<prefix>-<index>", the index zero-padded to the width of the largest one, so that they
// sort in generation order. The default prefix is "<generator>-N<primaries>-seed<seed>", with the
// generator's registered name.
std::vector<std::string> cluster_names(const GenerateOptions& o) {
  const std::string prefix = o.name_prefix.empty() ? request_for(o, 0).method + "-N" + std::to_string(o.primaries) +
                                                         "-seed" + std::to_string(o.seed)
                                                   : o.name_prefix;
  const std::size_t width = std::to_string(o.count - 1).size();
  std::vector<std::string> names;
  for (std::int64_t i = 0; i < o.count; ++i) {
    const std::string index = std::to_string(i);
    names.push_back(prefix + "-" + std::string(width - index.size(), '0') + index);
  }
  return names;
}

// Fails before any work when a name to be written is already in the library.
void require_free_names(const GenerateOptions& o, const std::vector<std::string>& names) {
  if (o.overwrite || !std::filesystem::exists(o.output)) return;
  const std::vector<std::string> stored = list_clusters(o.output);
  for (const std::string& name : names)
    if (std::find(stored.begin(), stored.end(), name) != stored.end())
      throw std::runtime_error(o.output + " already holds a cluster '" + name +
                               "' (choose another --name or --seed, or give --overwrite)");
}

void report_progress(std::size_t done, std::size_t total, const std::string& name, const Cluster& cluster,
                     const std::optional<RelaxationResult>& relaxation, double seconds) {
  std::cerr << "[" << done << "/" << total << "] " << name << ": N = " << cluster.size()
            << ", Rg = " << format_number(radius_of_gyration(cluster))
            << (relaxation ? ", relaxed in " + std::to_string(relaxation->steps) + " steps" : ", not relaxed") << ", "
            << format_number(seconds, 3) << " s\n";
}

// The engine's description of the run (engine/impact/cluster_generation.hpp).
ClusterGeneration generation_of(const GenerateOptions& o) {
  return {request_for(o, o.seed), o.relax, o.gamma_over_kn, o.poisson_ratio};
}

// Generates, relaxes and writes cluster `index` of the run.
void generate_one(const GenerateOptions& o, std::size_t index, const std::string& name, std::size_t total) {
  const auto started = std::chrono::steady_clock::now();
  const GeneratedCluster generated = generate_library_cluster(generation_of(o), index, name);
  if (!o.to_library())
    write_xyz_cluster(std::filesystem::path(o.xyz_file()), generated.cluster);
  else
    store_cluster(o.output, name, generated.cluster, generated.origin,
                  o.overwrite ? ExistingCluster::overwrite : ExistingCluster::reject);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - started;
  report_progress(index + 1, total, name, generated.cluster, generated.relaxation, elapsed.count());
}

void generate_clusters(const GenerateOptions& o) {
  check_generation(o);
  check_output(o);
  const std::vector<std::string> names = cluster_names(o);
  if (o.to_library()) require_free_names(o, names);
  const auto started = std::chrono::steady_clock::now();

  for (std::size_t i = 0; i < names.size(); ++i) {
    try {
      generate_one(o, i, names[i], names.size());
    } catch (const std::exception& error) {
      if (i == 0) throw;
      throw std::runtime_error(std::string(error.what()) + " (the " + std::to_string(i) +
                               " clusters before it are stored in " + o.output + ")");
    }
  }

  const std::chrono::duration<double> total = std::chrono::steady_clock::now() - started;
  if (!o.to_library())
    std::cout << "wrote " << names.front() << " to " << o.xyz_file();
  else
    std::cout << "stored " << names.size() << (names.size() == 1 ? " cluster" : " clusters") << " in " << o.output
              << " (" << names.front() << (names.size() > 1 ? " .. " + names.back() : "") << ")";
  std::cout << " in " << format_number(total.count(), 3) << " s\n";
}

void add_generate(CLI::App& cluster) {
  auto o = std::make_shared<GenerateOptions>();
  auto* generate = cluster.add_subcommand("generate", "Generate relaxed clusters into a library or an XYZ file");
  generate->footer(
      "Generators (the registry impact cases and studies use, docs/IMPACT.md): " + cluster_generator_names() +
      ".\nEach cluster is relaxed to mechanical equilibrium (JKR contacts at their equilibrium overlap) before it\n"
      "is stored; one whose relaxation does not converge or breaks contacts stops the run with an error.\n"
      "Cluster i (0, 1, ...) uses seed splitmix64(S, i): output i+1 of a SplitMix64 generator seeded with\n"
      "--seed S; the library records that seed with the cluster. Clusters are named PREFIX-i. Either output is\n"
      "a case's cluster file (/cluster/file/path; a library of several clusters with /cluster/file/name).\n"
      "Progress goes to stderr, one line per cluster.");
  generate
      ->add_option("--generator", o->generator,
                   "Generator: ballistic (BCCA; alias bcca), dlca (grown by the engine; --no-sintering for\n"
                   "unsintered) or tunable (FracVAL-type, hits --df and --kf)")
      ->capture_default_str();
  generate->add_option("--primaries,-N", o->primaries, "Primaries per cluster")->required();
  generate->add_option("--count", o->count, "Number of clusters")->capture_default_str();
  generate->add_option("--seed", o->seed, "Base seed S")->capture_default_str();
  generate->add_option("--diameter", o->diameter, "Geometric mean primary diameter, d")->capture_default_str();
  generate
      ->add_option("--gsd", o->geometric_standard_deviation,
                   "Geometric standard deviation of lognormal diameters (1: monodisperse; ballistic, tunable)")
      ->capture_default_str();
  generate->add_option("--df", o->fractal_dimension, "Fractal dimension D_f of the tunable generator (1.5 to 2.8)");
  generate->add_option("--kf", o->prefactor,
                       "Fractal prefactor k_f of the tunable generator (FracVAL's Rg of solid spheres)");
  auto* sintering = generate->add_flag("--sintering,!--no-sintering", o->sintering,
                                       "dlca: grow with (default) or without rolling and twisting resistance");
  generate->add_flag("--relax,!--no-relax", o->relax,
                     "Relax each cluster to JKR equilibrium before storing it (default; an unconverged or broken\n"
                     "relaxation is an error)");
  generate->add_option("--gamma-over-kn", o->gamma_over_kn, "Surface energy over normal stiffness for relaxing")
      ->capture_default_str();
  generate->add_option("--poisson", o->poisson_ratio, "Poisson ratio for relaxing")->capture_default_str();
  auto* output = generate->add_option("--output,-o", o->output,
                                      "Output: a cluster library (HDF5) to add the clusters to if it ends in .h5 or\n"
                                      ".hdf5, else an XYZ file (one cluster)");
  generate->add_option("--name", o->name_prefix, "Name prefix in a library (default GENERATOR-N<primaries>-seed<S>)");
  generate->add_flag("--overwrite", o->overwrite, "Replace clusters of the same name in a library");
  auto* xyz =
      generate->add_option("--xyz", o->xyz, "Write the (single) cluster to this XYZ file (as --output FILE.xyz)");
  xyz->excludes(output);
  generate->callback([o, sintering] {
    o->sintering_given = sintering->count() > 0;
    run_reporting_errors("generate", [&] { generate_clusters(*o); });
  });
}

// ---- analyze ---------------------------------------------------------------------------------

struct AnalyzeOptions {
  std::string input;
  std::string name;
  bool json_output = false;
};

void print_table(const std::vector<NamedCluster>& clusters, const std::vector<ClusterAnalysis>& analyses) {
  const std::vector<std::string> header{"name",  "N",          "Rg",      "extent",   "contacts",
                                        "coord", "components", "filling", "porosity", "Df(m-r)"};
  std::vector<std::vector<std::string>> rows{header};
  for (std::size_t i = 0; i < clusters.size(); ++i) {
    const ClusterAnalysis& a = analyses[i];
    rows.push_back({clusters[i].name, std::to_string(a.primary_count), format_number(a.radius_of_gyration),
                    format_number(a.maximum_extent), std::to_string(a.contact_count),
                    format_number(a.mean_coordination_number, 3), std::to_string(a.component_sizes.size()),
                    format_number(a.filling_factor), format_number(a.porosity),
                    format_number(a.mass_radius_dimension, 3)});
  }
  std::vector<std::size_t> width(header.size(), 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  for (const auto& row : rows) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const std::string padding(width[c] - row[c].size(), ' ');
      line += c == 0 ? row[c] + padding : "  " + padding + row[c];
    }
    std::cout << line << "\n";
  }
}

void print_ensemble(const EnsembleFractalFit& ensemble) {
  if (!ensemble.attempted) return;
  if (!ensemble.fit) {
    std::cout << "\nensemble fit N = kf (Rg/a)^Df: not possible: " << ensemble.failure << "\n";
    return;
  }
  const FractalScalingFit& f = *ensemble.fit;
  std::cout << "\nensemble fit N = kf (Rg/a)^Df over " << f.sample_count << " clusters (N " << f.min_primary_count
            << " to " << f.max_primary_count << ", a = " << format_number(ensemble.primary_radius)
            << "): Df = " << format_number(f.fractal_dimension) << " +- "
            << format_number(f.fractal_dimension_standard_error, 2) << ", kf = " << format_number(f.prefactor) << "\n";
}

json analysis_json(const NamedCluster& each, const ClusterAnalysis& a) {
  json entry = {{"name", each.name},
                {"primary_count", a.primary_count},
                {"radius_of_gyration", a.radius_of_gyration},
                {"maximum_extent", a.maximum_extent},
                {"contact_count", a.contact_count},
                {"mean_coordination_number", a.mean_coordination_number},
                {"component_count", a.component_sizes.size()},
                {"component_sizes", a.component_sizes},
                {"filling_factor", a.filling_factor},
                {"porosity", a.porosity},
                {"mass_radius_dimension", a.mass_radius_dimension}};
  if (each.metadata) {
    const ClusterOrigin& origin = each.metadata->origin;
    entry["generator"] = origin.generator;
    entry["seed"] = origin.seed;
    entry["relaxed"] = origin.relaxed;
    entry["prefactor"] = origin.prefactor;
  }
  return entry;
}

json ensemble_json(const EnsembleFractalFit& ensemble) {
  if (!ensemble.attempted) return nullptr;
  if (!ensemble.fit) return {{"error", ensemble.failure}};
  const FractalScalingFit& f = *ensemble.fit;
  return {{"fractal_dimension", f.fractal_dimension},
          {"fractal_dimension_standard_error", f.fractal_dimension_standard_error},
          {"prefactor", f.prefactor},
          {"primary_radius", ensemble.primary_radius},
          {"sample_count", f.sample_count},
          {"primary_count_range", {f.min_primary_count, f.max_primary_count}},
          {"normalised_radius_range", {f.min_normalised_radius, f.max_normalised_radius}}};
}

void analyze_clusters(const AnalyzeOptions& o) {
  std::vector<NamedCluster> sources = read_cluster_file(o.input, o.name);
  std::vector<Cluster> clusters;
  std::vector<ClusterAnalysis> analyses;
  for (NamedCluster& source : sources) {
    analyses.push_back(analyse_cluster(source.cluster));
    clusters.push_back(std::move(source.cluster));  // the sources keep their names and metadata
  }
  const EnsembleFractalFit ensemble = fit_cluster_ensemble(clusters, analyses);
  if (o.json_output) {
    json entries = json::array();
    for (std::size_t i = 0; i < sources.size(); ++i) entries.push_back(analysis_json(sources[i], analyses[i]));
    const json report{{"file", o.input}, {"clusters", entries}, {"ensemble_fit", ensemble_json(ensemble)}};
    std::cout << report.dump(2) << "\n";
    return;
  }
  print_table(sources, analyses);
  print_ensemble(ensemble);
}

void add_analyze(CLI::App& cluster) {
  auto o = std::make_shared<AnalyzeOptions>();
  auto* analyze = cluster.add_subcommand("analyze", "Print the structure of the clusters in a file");
  analyze->footer(
      "Per cluster: N, Rg, extent, contacts, mean coordination, components, filling factor, porosity and\n"
      "mass-radius fractal dimension (n/a below Rg = 8 d); for a library with several cluster sizes also the\n"
      "ensemble fit N = kf (Rg/a)^Df with the standard error of Df.");
  analyze->alias("analyse");
  analyze->add_option("FILE", o->input, "XYZ file or cluster library (HDF5)")->required();
  analyze->add_option("--name", o->name, "Only this cluster of the library (default: all)");
  analyze->add_flag("--json", o->json_output, "Print JSON instead of a table");
  analyze->callback([o] { run_reporting_errors("analyze", [&] { analyze_clusters(*o); }); });
}

// ---- convert ---------------------------------------------------------------------------------

struct ConvertOptions {
  std::string input;
  std::string output;
  std::string name;
  bool overwrite = false;
};

void convert_clusters(const ConvertOptions& o) {
  const std::size_t count = convert_cluster_file(o.input, o.output, o.name,
                                                 o.overwrite ? ExistingCluster::overwrite : ExistingCluster::reject);
  std::cout << "wrote " << count << (count == 1 ? " cluster" : " clusters") << " to " << o.output << "\n";
}

void add_convert(CLI::App& cluster) {
  auto o = std::make_shared<ConvertOptions>();
  auto* convert = cluster.add_subcommand("convert", "Convert clusters between XYZ files and cluster libraries");
  convert->footer(
      "OUT is a library if it ends in .h5 or .hdf5, an XYZ file (replaced if it exists) otherwise; the kind of\n"
      "IN is told from its content.");
  convert->add_option("IN", o->input, "XYZ file or cluster library")->required();
  convert->add_option("OUT", o->output, "XYZ file or cluster library")->required();
  convert->add_option("--name", o->name,
                      "Library input: the cluster to convert (needed for XYZ output; default: all). XYZ input: the\n"
                      "name to store it under (default: the file name without extension)");
  convert->add_flag("--overwrite", o->overwrite, "Replace a cluster of the same name in the output library");
  convert->callback([o] { run_reporting_errors("convert", [&] { convert_clusters(*o); }); });
}

}  // namespace

void add_cluster_command(CLI::App& app) {
  auto* cluster = app.add_subcommand("cluster", "Generate, analyse or convert fractal clusters");
  cluster->require_subcommand(1);
  add_generate(*cluster);
  add_analyze(*cluster);
  add_convert(*cluster);
}

}  // namespace aerobreak
