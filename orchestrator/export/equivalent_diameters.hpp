#pragma once

namespace aerobreak {

// Equivalent diameters of an aggregate of N primaries of diameter d (docs/EXPORT.md, "Sizes").
//
// Volume-equivalent: the sphere of the same solid volume, d_ve = d N^(1/3).
//
// Mobility-equivalent: in the free-molecular regime (primaries much smaller than the gas mean free
// path, 67.3 nm in air at 296 K and 101.3 kPa) the mobility diameter of a fractal aggregate equals
// its projected-area-equivalent diameter (Rogak, Flagan & Nguyen, Aerosol Sci. Technol. 18 (1993)
// 25; Sorensen, Aerosol Sci. Technol. 45 (2011) 765), and for aggregates of fractal dimension near
// 2 (ballistic clusters: 1.9-2.05) that equality holds through the transition regime as well (Rogak
// et al. 1993, their measurements on TiO2 and Si agglomerates); the projected area scales with N as
// N = k_a (d_a/d)^(2 D_alpha) with k_a = 1 and D_alpha = 1.08 (Eggersdorfer, Kadau, Herrmann &
// Pratsinis, J. Aerosol Sci. 46 (2012) 7; Eggersdorfer & Pratsinis, Aerosol Sci. Technol. 46 (2012)
// 347), so d_mob = d N^(1/(2 D_alpha)) = d N^0.463, close to Sorensen's N^0.46.
//
// Aerodynamic: the diameter of the sphere of density 1000 kg/m^3 that settles at the aggregate's
// speed. Equal settling speeds, m g Cc(d_mob) / (3 pi mu d_mob) = rho_0 (pi/6) d_ae^3 g Cc(d_ae) /
// (3 pi mu d_ae) with m = rho_p (pi/6) d_ve^3, give rho_0 d_ae^2 Cc(d_ae) = rho_p d_ve^3 Cc(d_mob) /
// d_mob (DeCarlo, Slowik, Worsnop, Davidovits & Jimenez, Aerosol Sci. Technol. 38 (2004) 1185),
// solved for d_ae by bisection; Cc the Cunningham slip correction 1 + Kn (alpha + beta exp(-gamma /
// Kn)), Kn = 2 lambda / d, with lambda = 67.3 nm, alpha = 1.165, beta = 0.483, gamma = 0.997 for air
// at 296.15 K and 101.3 kPa (Kim, Mulholland, Kukuck & Pui, J. Res. NIST 110 (2005) 31). SI only:
// it needs the primaries' diameter and density.
inline constexpr double kProjectedAreaExponent = 1.08;  // D_alpha
inline constexpr double kProjectedAreaPrefactor = 1.0;  // k_a
inline constexpr double kAirMeanFreePath = 67.3e-9;     // m, air at 296.15 K and 101.3 kPa
inline constexpr double kUnitDensity = 1000.0;          // kg/m^3, the aerodynamic reference sphere

// In units of d.
double volume_equivalent_diameter(double primaries);
double mobility_equivalent_diameter(double primaries);
// In m, from N, d (m) and the primaries' density (kg/m^3).
double aerodynamic_diameter(double primaries, double primary_diameter, double density);
// The Cunningham slip correction of a sphere of diameter `diameter` (m) in air.
double slip_correction(double diameter);

enum class DiameterType { mobility, volume, aerodynamic };
// N of an aggregate of that diameter: mobility and volume in units of d, aerodynamic in m (with d
// in m and the density); the inverse of the functions above.
double primaries_of_diameter(DiameterType type, double diameter, double primary_diameter = 0.0, double density = 0.0);

}  // namespace aerobreak
