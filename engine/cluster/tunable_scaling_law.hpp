#pragma once
#include <cstddef>
#include <span>

#include "engine/cluster/cluster.hpp"
#include "engine/core/vec3.hpp"

namespace aerobreak {

// The relations the tunable generator imposes (Moran, Fuentes, Liu & Yon 2019, Comput. Phys.
// Commun. 239 225, "FracVAL"; Filippov, Zurita & Rosner 2000, J. Colloid Interface Sci. 229 261).
// Masses are proportional to r^3 (one material density) and every centre of mass is mass-weighted
// (FracVAL eq. 5).

// Which radius of gyration the scaling law constrains; both are mass-weighted about the centre of
// mass. The two differ by the primaries' own extent: Rg_solid^2 = Rg_point^2 + (3/5) <r^2>_m.
enum class GyrationConvention {
  // Each primary a uniform solid sphere that adds its own (3/5) r^2 (FracVAL eq. 4): a single
  // primary has Rg = sqrt(3/5) r. FracVAL's convention, so its (Df, kf) ranges carry over.
  solid_spheres,
  // Primaries as point masses at their centres: radius_of_gyration() of cluster_analysis.hpp.
  point_masses,
};

// The fractal scaling law of both papers, n = kf (Rg / a)^Df, solved for Rg: Rg = a (n /
// kf)^(1/Df), with n the number of primaries and a their geometric mean radius (as FracVAL takes
// it).
struct FractalLaw {
  double fractal_dimension = 0.0;
  double prefactor = 0.0;
  GyrationConvention convention = GyrationConvention::solid_spheres;

  double gyration_radius(double primary_count, double primary_radius) const;
};

// A primary's own contribution to Rg^2: (3/5) r^2 for a solid sphere, 0 for a point mass.
double primary_gyration_squared(double radius, GyrationConvention convention);

// Rg of a set of primaries under the convention (FracVAL eqs. 4 and 5). Throws
// std::invalid_argument for an empty set or mismatched sizes.
double gyration_radius(std::span<const Vec3> positions, std::span<const double> radii, GyrationConvention convention);
double gyration_radius(const Cluster& cluster, GyrationConvention convention);

// exp(mean ln r): the primary radius a of the scaling law. Throws std::invalid_argument for an
// empty set or a non-positive radius.
double geometric_mean_radius(std::span<const double> radii);

// Squared distance between the centres of mass of two aggregates (masses m1, m2, radii of
// gyration rg1, rg2) that makes their union have radius of gyration rg: by the parallel-axis
// theorem (m1 + m2) rg^2 = m1 rg1^2 + m2 rg2^2 + m1 m2 / (m1 + m2) Gamma^2, so
//   Gamma^2 = M^2 / (m1 m2) rg^2 - M / m2 rg1^2 - M / m1 rg2^2,  M = m1 + m2
// (FracVAL eq. 6; with a monomer as the second aggregate it is Filippov et al.'s Gamma_pc, with
// two clusters their Gamma_cc). A negative value means the target is unreachable at any distance.
double centre_distance_squared(double m1, double rg1, double m2, double rg2, double rg);

}  // namespace aerobreak
