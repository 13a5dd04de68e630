#include "orchestrator/cli/cluster_command.hpp"

#include <algorithm>
#include <array>
#include <cctype>
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
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "engine/cluster/cluster_analysis.hpp"
#include "engine/cluster/fractal_scaling_fit.hpp"
#include "engine/core/units.hpp"
#include "engine/dem/impact_placement.hpp"
#include "engine/dem/relaxation.hpp"
#include "engine/impact/cluster_generators.hpp"
#include "engine/io/cluster_library.hpp"
#include "engine/io/xyz.hpp"

namespace aerobreak {
namespace {

using json = nlohmann::ordered_json;  // keys in the order written, for readable output

constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();

// ---- reporting -------------------------------------------------------------------------------

// Reports a failure of `aerobreak cluster <verb>` on stderr and ends the program with status 1
// (CLI11 returns a RuntimeError's exit code without printing anything itself).
[[noreturn]] void fail_command(const std::string& verb, const std::string& message) {
  std::cerr << "aerobreak cluster " << verb << ": error: " << message << "\n";
  throw CLI::RuntimeError(1);
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

// ---- input files -----------------------------------------------------------------------------

// One cluster from a file, with its library metadata when it came from a library.
struct NamedCluster {
  std::string name;
  Cluster cluster;
  std::optional<ClusterMetadata> metadata;
};

void require_existing_file(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("no such file: " + path);
}

NamedCluster read_library_entry(const std::string& library, const std::string& name) {
  StoredCluster stored = read_cluster(library, name);
  return {stored.name, std::move(stored.cluster), std::move(stored.metadata)};
}

// The clusters of a library: the one named, or all of them for an empty name.
std::vector<NamedCluster> read_library(const std::string& library, const std::string& name) {
  std::vector<NamedCluster> clusters;
  const std::vector<std::string> names = name.empty() ? list_clusters(library) : std::vector<std::string>{name};
  for (const std::string& each : names) clusters.push_back(read_library_entry(library, each));
  return clusters;
}

// A text file's cluster, named after the file.
NamedCluster read_text_cluster(const std::string& path) {
  NamedCluster named{std::filesystem::path(path).stem().string(), read_xyz_cluster(std::filesystem::path(path)), {}};
  if (named.cluster.size() == 0) throw std::runtime_error(path + ": no particles in the file");
  return named;
}

// Output files ending in .h5 or .hdf5 are cluster libraries; any other name is a text (XYZ) file.
bool names_library(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".h5" || extension == ".hdf5";
}

// "a, b, c", with at most `shown` names and a count of the rest.
std::string joined(const std::vector<std::string>& names, std::size_t shown = 10) {
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < shown; ++i) text += (i == 0 ? "" : ", ") + names[i];
  if (names.size() > shown) text += " and " + std::to_string(names.size() - shown) + " more";
  return text;
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

bool GenerateOptions::to_library() const { return xyz.empty() && names_library(output); }

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
      {"method", "--generator"}, {"primaries", "--primaries"}, {"geometric_mean_diameter", "--diameter"},
      {"geometric_standard_deviation", "--gsd"}, {"fractal_dimension", "--df"}, {"prefactor", "--kf"},
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
    throw std::runtime_error("give either --output FILE (.h5 or .hdf5: a cluster library; otherwise XYZ) or --xyz FILE");
  if (!o.to_library() && o.count != 1)
    throw std::runtime_error("an XYZ file holds one cluster; use --output FILE.h5 for --count " +
                             std::to_string(o.count));
  if (!o.to_library() && (!o.name_prefix.empty() || o.overwrite))
    throw std::runtime_error("--name and --overwrite apply to a cluster library (--output FILE.h5)");
}

// Seed of cluster `index` (0, 1, ...) of a generation with base seed `base`: output index + 1 of a
// SplitMix64 generator seeded with `base` (Steele, Lea & Flood 2014), so that neighbouring base
// seeds do not share clusters.
std::uint64_t derived_seed(std::uint64_t base, std::uint64_t index) {
  std::uint64_t z = base + (index + 1) * 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
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

// In reduced units with the default contact model, of which relax_cluster uses the normal law only:
// JKR with displacement-controlled separation.
RelaxationResult relax_generated(const Cluster& cluster, const GenerateOptions& o) {
  const Material material = reduced_material(o.gamma_over_kn, o.poisson_ratio);
  return relax_cluster(particles_from_cluster(cluster, material.density), {material}, ContactModelSpec{});
}

// docs/MODEL.md 11.1: a cluster handed to an impact must be at mechanical equilibrium and intact.
void require_intact(const RelaxationResult& relaxation, const std::string& name, std::uint64_t seed) {
  const std::string which = "cluster " + name + " (seed " + std::to_string(seed) + ")";
  if (!relaxation.converged)
    throw std::runtime_error(which + ": relaxation did not converge in " + std::to_string(relaxation.steps) +
                             " steps (largest net force " + format_number(relaxation.largest_force) +
                             " times the primary's own F_c); not stored");
  if (relaxation.contacts_broken > 0)
    throw std::runtime_error(which + ": relaxation broke " + std::to_string(relaxation.contacts_broken) +
                             " contacts (the cluster came apart); not stored");
}

// What the library records of a generation: the registry's request (as a case would name it),
// the diameter, the seed derivation and the relaxation.
json generation_parameters(const GenerateOptions& o, const GeneratorRequest& request, std::size_t index,
                           const std::optional<RelaxationResult>& relaxation) {
  json parameters = generator_document(request);
  parameters.erase("seed");
  parameters["geometric_mean_diameter"] = o.diameter;
  parameters["base_seed"] = o.seed;
  parameters["index"] = index;
  parameters["seed_derivation"] = "splitmix64 output index+1 from base_seed";
  if (generator_takes(request.method, "fractal_dimension")) parameters["gyration_convention"] = "solid_spheres";
  parameters["relaxation"] = nullptr;
  if (relaxation)
    parameters["relaxation"] = {{"normal_law", "jkr"},
                                {"gamma_over_kn", o.gamma_over_kn},
                                {"poisson_ratio", o.poisson_ratio},
                                {"steps", relaxation->steps},
                                {"contacts", relaxation->contacts},
                                {"largest_force_over_pull_off", relaxation->largest_force}};
  return parameters;
}

void report_progress(std::size_t done, std::size_t total, const std::string& name, const Cluster& cluster,
                     const std::optional<RelaxationResult>& relaxation, double seconds) {
  std::cerr << "[" << done << "/" << total << "] " << name << ": N = " << cluster.size()
            << ", Rg = " << format_number(radius_of_gyration(cluster))
            << (relaxation ? ", relaxed in " + std::to_string(relaxation->steps) + " steps" : ", not relaxed")
            << ", " << format_number(seconds, 3) << " s\n";
}

// Generates, relaxes and writes cluster `index` of the run.
void generate_one(const GenerateOptions& o, std::size_t index, const std::string& name, std::size_t total) {
  const auto started = std::chrono::steady_clock::now();
  const GeneratorRequest request = request_for(o, derived_seed(o.seed, index));
  Cluster cluster = generate_cluster(request);
  std::optional<RelaxationResult> relaxation;
  if (o.relax) {
    relaxation = relax_generated(cluster, o);
    require_intact(*relaxation, name, request.seed);
    cluster = cluster_from_particles(relaxation->particles);
  }
  if (!o.to_library()) {
    write_xyz_cluster(std::filesystem::path(o.xyz_file()), cluster);
  } else {
    // k_f where the generator imposes one.
    const double prefactor = generator_takes(request.method, "prefactor") ? request.prefactor : kNotGiven;
    const ClusterOrigin origin{request.method, generation_parameters(o, request, index, relaxation).dump(),
                               request.seed, prefactor, o.relax};
    store_cluster(o.output, name, cluster, origin, o.overwrite ? ExistingCluster::overwrite : ExistingCluster::reject);
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - started;
  report_progress(index + 1, total, name, cluster, relaxation, elapsed.count());
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
  generate->add_option("--gsd", o->geometric_standard_deviation,
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
  auto* xyz = generate->add_option("--xyz", o->xyz, "Write the (single) cluster to this XYZ file (as --output FILE.xyz)");
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

struct AnalysedCluster {
  NamedCluster source;
  ClusterAnalysis analysis;
};

std::vector<NamedCluster> read_for_analysis(const AnalyzeOptions& o) {
  require_existing_file(o.input);
  if (is_hdf5_file(o.input)) return read_library(o.input, o.name);
  if (!o.name.empty())
    throw std::runtime_error("--name selects a cluster of a library, and " + o.input + " is not an HDF5 file");
  return {read_text_cluster(o.input)};
}

double mean_primary_radius(const std::vector<AnalysedCluster>& clusters) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const AnalysedCluster& each : clusters) {
    for (const double r : each.source.cluster.radius) sum += r;
    count += each.source.cluster.size();
  }
  return sum / static_cast<double>(count);
}

std::size_t distinct_sizes(const std::vector<AnalysedCluster>& clusters) {
  std::set<std::size_t> sizes;
  for (const AnalysedCluster& each : clusters) sizes.insert(each.analysis.primary_count);
  return sizes.size();
}

// The ensemble fit N = k_f (Rg/a)^D_f (report figure 2b): attempted when the clusters have
// several sizes; holds the fit or the reason it could not be made.
struct EnsembleFit {
  bool attempted = false;
  std::optional<FractalScalingFit> fit;
  double primary_radius = 0.0;
  std::string failure;
};

EnsembleFit fit_ensemble(const std::vector<AnalysedCluster>& clusters) {
  EnsembleFit ensemble;
  if (distinct_sizes(clusters) < 2) return ensemble;
  ensemble.attempted = true;
  ensemble.primary_radius = mean_primary_radius(clusters);
  std::vector<SizeRadiusSample> samples;
  for (const AnalysedCluster& each : clusters)
    samples.push_back({static_cast<double>(each.analysis.primary_count), each.analysis.radius_of_gyration});
  try {
    ensemble.fit = fit_fractal_scaling(samples, ensemble.primary_radius);
  } catch (const std::invalid_argument& error) {
    ensemble.failure = error.what();
  }
  return ensemble;
}

void print_table(const std::vector<AnalysedCluster>& clusters) {
  const std::vector<std::string> header{"name",      "N",          "Rg",      "extent",   "contacts",
                                        "coord", "components", "filling", "porosity", "Df(m-r)"};
  std::vector<std::vector<std::string>> rows{header};
  for (const AnalysedCluster& each : clusters) {
    const ClusterAnalysis& a = each.analysis;
    rows.push_back({each.source.name, std::to_string(a.primary_count), format_number(a.radius_of_gyration),
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

void print_ensemble(const EnsembleFit& ensemble) {
  if (!ensemble.attempted) return;
  if (!ensemble.fit) {
    std::cout << "\nensemble fit N = kf (Rg/a)^Df: not possible: " << ensemble.failure << "\n";
    return;
  }
  const FractalScalingFit& f = *ensemble.fit;
  std::cout << "\nensemble fit N = kf (Rg/a)^Df over " << f.sample_count << " clusters (N " << f.min_primary_count
            << " to " << f.max_primary_count << ", a = " << format_number(ensemble.primary_radius) << "): Df = "
            << format_number(f.fractal_dimension) << " +- " << format_number(f.fractal_dimension_standard_error, 2)
            << ", kf = " << format_number(f.prefactor) << "\n";
}

json analysis_json(const AnalysedCluster& each) {
  const ClusterAnalysis& a = each.analysis;
  json entry = {{"name", each.source.name},
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
  if (each.source.metadata) {
    const ClusterOrigin& origin = each.source.metadata->origin;
    entry["generator"] = origin.generator;
    entry["seed"] = origin.seed;
    entry["relaxed"] = origin.relaxed;
    entry["prefactor"] = origin.prefactor;
  }
  return entry;
}

json ensemble_json(const EnsembleFit& ensemble) {
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
  std::vector<AnalysedCluster> clusters;
  for (NamedCluster& source : read_for_analysis(o)) {
    const ClusterAnalysis analysis = analyse_cluster(source.cluster);
    clusters.push_back({std::move(source), analysis});
  }
  const EnsembleFit ensemble = fit_ensemble(clusters);
  if (o.json_output) {
    json entries = json::array();
    for (const AnalysedCluster& each : clusters) entries.push_back(analysis_json(each));
    const json report{{"file", o.input}, {"clusters", entries}, {"ensemble_fit", ensemble_json(ensemble)}};
    std::cout << report.dump(2) << "\n";
    return;
  }
  print_table(clusters);
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

ClusterOrigin imported_origin(const std::string& source) {
  ClusterOrigin origin;
  origin.generator = "xyz";
  origin.parameters = json{{"source", source}}.dump();
  return origin;
}

std::vector<NamedCluster> read_for_conversion(const ConvertOptions& o, bool to_library) {
  require_existing_file(o.input);
  if (!is_hdf5_file(o.input)) {
    NamedCluster text = read_text_cluster(o.input);
    if (!o.name.empty()) text.name = o.name;
    return {std::move(text)};
  }
  if (o.name.empty() && !to_library)
    throw std::runtime_error("converting a library to XYZ needs --name (" + o.input +
                             " holds: " + joined(list_clusters(o.input)) + ")");
  return read_library(o.input, o.name);
}

void convert_clusters(const ConvertOptions& o) {
  const bool to_library = names_library(o.output);
  const std::vector<NamedCluster> clusters = read_for_conversion(o, to_library);
  for (const NamedCluster& each : clusters) {
    if (!to_library) {
      write_xyz_cluster(std::filesystem::path(o.output), each.cluster);
      continue;
    }
    const ClusterOrigin origin = each.metadata ? each.metadata->origin : imported_origin(o.input);
    store_cluster(o.output, each.name, each.cluster, origin,
                  o.overwrite ? ExistingCluster::overwrite : ExistingCluster::reject);
  }
  std::cout << "wrote " << clusters.size() << (clusters.size() == 1 ? " cluster" : " clusters") << " to "
            << o.output << "\n";
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
