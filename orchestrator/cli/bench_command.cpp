#include "orchestrator/cli/bench_command.hpp"

#include <cstdio>
#include <filesystem>
#include <map>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/random_stream.hpp"
#include "engine/core/run_clock.hpp"
#include "engine/core/units.hpp"
#include "engine/core/version.hpp"
#include "engine/dem/impact_placement.hpp"
#include "engine/dem/relaxation.hpp"
#include "engine/dem/simulation.hpp"
#include "engine/io/xyz.hpp"

namespace aerobreak {
namespace {

struct BenchOptions {
  std::vector<std::size_t> sizes{1000, 4000};
  std::int64_t steps = 2000;
  double speed = 0.02;
  double gamma_over_kn = 0.001;
  double poisson = 0.3;
  double friction = 0.5;
  double critical_rolling = 0.01;
  double dissipative_time = 0.05;
  bool wall_adhesion = true;
  bool rolling = true;
  bool twisting = true;
  double time_step = 0.0;  // 0: automatic
  JkrSeparation separation = JkrSeparation::displacement;
  std::uint64_t seed = 1;
  int wavefront_depth = SimulationSettings{}.wavefront_depth;
  std::size_t wavefront_min_particles = SimulationSettings{}.wavefront_min_particles;
  std::string export_dir;
};

ContactModelSpec full_model(const BenchOptions& o) {
  ContactModelSpec spec;
  spec.normal = NormalLaw::jkr;
  spec.separation = o.separation;
  spec.dissipative_time = o.dissipative_time;
  spec.tangential = true;
  spec.friction = o.friction;
  spec.damping = o.dissipative_time > 0.0 ? DampingLaw::viscoelastic : DampingLaw::none;
  spec.rolling = o.rolling;
  spec.critical_rolling = o.critical_rolling;
  spec.twisting = o.twisting;
  return spec;
}

void export_case(const BenchOptions& o, const Simulation& sim, std::size_t n) {
  const std::filesystem::path dir(o.export_dir);
  std::filesystem::create_directories(dir);
  const std::string stem = "bench_N" + std::to_string(n);
  write_xyz_cluster(dir / (stem + ".xyz"), cluster_from_particles(sim.particles()));
  const nlohmann::json params = {{"primaries", n},
                                 {"time_step", sim.time_step()},
                                 {"speed", o.speed},
                                 {"gamma_over_kn", o.gamma_over_kn},
                                 {"poisson_ratio", o.poisson},
                                 {"friction", o.friction},
                                 {"critical_rolling", o.critical_rolling},
                                 {"dissipative_time", o.dissipative_time},
                                 {"wall_adhesion", o.wall_adhesion},
                                 {"rolling", o.rolling},
                                 {"twisting", o.twisting},
                                 {"separation", o.separation == JkrSeparation::force ? "force" : "displacement"},
                                 {"steps", o.steps},
                                 {"seed", o.seed}};
  std::ofstream(dir / (stem + ".json")) << params.dump(2) << "\n";
}

// The contact model and wall as the options set them, for the header line.
std::string model_summary(const BenchOptions& o) {
  char damping[64] = "no damping";
  if (o.dissipative_time > 0.0)
    std::snprintf(damping, sizeof damping, "visco-elastic damping (A = %g tau)", o.dissipative_time);
  char text[256];
  std::snprintf(text, sizeof text, "JKR (%s rule) + %s + Mindlin (mu = %g) + %s + %s; %s wall",
                o.separation == JkrSeparation::force ? "force" : "displacement", damping, o.friction,
                o.rolling ? "rolling" : "no rolling", o.twisting ? "twisting" : "no twisting",
                o.wall_adhesion ? "adhesive" : "non-adhesive");
  return text;
}

void run_bench(const BenchOptions& o) {
  const Material material = reduced_material(o.gamma_over_kn, o.poisson);
  std::printf("aerobreak %s bench: BCCA cluster, relaxed, hitting a wall at %.3g d/tau; %s; gamma/k_n = %g; one core\n",
              std::string(version()).c_str(), o.speed, model_summary(o).c_str(), o.gamma_over_kn);
  std::printf("%9s %9s %10s %12s %10s %14s %12s %10s %10s %10s %10s %14s\n", "N", "contacts", "steps", "dt [tau]",
              "seconds", "particle-steps/s", "ns/p-step", "pairs/N", "rebuilds", "wavefront", "CPU s", "p-steps/CPU s");
  for (std::size_t n : o.sizes) {
    const Cluster cluster = ballistic_cluster_cluster_aggregation({n, 1.0, 1.0}, o.seed);
    const RelaxationResult relaxed =
        relax_cluster(particles_from_cluster(cluster, material.density), {material}, full_model(o));
    RandomStream orientation(o.seed + 1);
    Wall wall;
    wall.adhesive = o.wall_adhesion;
    Particles placed = place_for_impact(relaxed.particles, orientation.rotation(), wall, 0.01, {0.0, 0.0, -o.speed});
    SimulationSettings settings;
    settings.initial_bond_gap = 1e-6;
    settings.speed_scale = o.speed;
    settings.time_step = o.time_step;
    // One step for the whole run (the automatic one at the impact speed, or the given one): the
    // cost per particle-step compares, and LAMMPS (compare.sh) runs the same step.
    settings.adaptive_time_step = false;
    settings.wavefront_depth = o.wavefront_depth;
    settings.wavefront_min_particles = o.wavefront_min_particles;
    Simulation sim(std::move(placed), {material}, {wall}, full_model(o), settings);
    if (!o.export_dir.empty()) export_case(o, sim, n);

    // Every size runs the same window of the impact, so that the contact load per particle compares.
    const auto rebuilds0 = sim.neighbor_builds();
    const RunClock clock;
    sim.run(o.steps);
    const ElapsedTimes elapsed = clock.elapsed();
    const std::int64_t steps = o.steps;
    const double particle_steps = static_cast<double>(n) * static_cast<double>(steps);
    const double rate = particle_steps / elapsed.wall_seconds;
    // The share of the steps that ran in wavefronts (SimulationSettings::wavefront_depth).
    const double in_wavefronts = static_cast<double>(sim.wavefront_steps()) / static_cast<double>(steps);
    std::printf("%9zu %9zu %10lld %12.5g %10.3f %14.4g %12.1f %10.2f %10llu %9.0f%% %10.3f %14.4g\n", n,
                sim.contacts().size(), static_cast<long long>(steps), sim.time_step(), elapsed.wall_seconds, rate,
                1e9 / rate, static_cast<double>(sim.neighbor_pairs()) / static_cast<double>(n),
                static_cast<unsigned long long>(sim.neighbor_builds() - rebuilds0), 100.0 * in_wavefronts,
                elapsed.cpu_seconds, particle_steps / elapsed.cpu_seconds);
    std::fflush(stdout);
  }
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  auto* bench = app.add_subcommand("bench", "Measure engine speed in particle-steps per second");
  bench->add_option("--sizes", options->sizes, "Cluster sizes (primaries)")->delimiter(',')->capture_default_str();
  bench->add_option("--steps", options->steps, "Time steps per size (the same impact window for every size)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  bench->add_option("--speed", options->speed, "Impact speed, d/tau (tau = sqrt(m/k_n))")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  bench->add_option("--gamma-over-kn", options->gamma_over_kn, "Surface energy over normal stiffness (eq 7)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  bench->add_option("--friction", options->friction, "Friction coefficient mu")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  bench->add_option("--xi-crit", options->critical_rolling, "Critical rolling displacement, d")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  bench->add_option("--damping", options->dissipative_time, "Visco-elastic dissipative time A, tau")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  bench->add_flag("!--no-wall-adhesion", options->wall_adhesion, "Wall without adhesion (Hertz)");
  bench->add_flag("!--no-rolling", options->rolling, "No rolling resistance");
  bench->add_flag("!--no-twisting", options->twisting, "No twisting resistance");
  bench->add_option("--time-step", options->time_step, "Fixed time step, tau (default: automatic)")
      ->check(CLI::PositiveNumber);
  bench
      ->add_option("--separation", options->separation,
                   "Where JKR contacts let go: displacement (at -delta_c, eq 3) or force (at F = -F_c, as LAMMPS)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, JkrSeparation>{
          {"displacement", JkrSeparation::displacement}, {"force", JkrSeparation::force}}))
      ->capture_default_str();
  bench
      ->add_option("--wavefront-depth", options->wavefront_depth,
                   "Steps whose force passes run together (1: one step at a time; the results are the same)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  bench
      ->add_option("--wavefront-from", options->wavefront_min_particles,
                   "Fewest particles for which steps run in wavefronts")
      ->capture_default_str();
  bench->add_option("--seed", options->seed, "Seed of the cluster and its orientation")->capture_default_str();
  bench->add_option("--export", options->export_dir,
                    "Write each placed cluster (XYZ) and its parameters (JSON) here, for the LAMMPS peer run");
  bench->callback([options] { run_bench(*options); });
}

}  // namespace aerobreak
