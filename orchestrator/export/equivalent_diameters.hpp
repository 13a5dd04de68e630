#pragma once

namespace aerobreak {

// Equivalent diameters of an aggregate of N primaries of diameter d (docs/EXPORT.md, "Sizes"),
// in units of d.
//
// Volume-equivalent: the sphere of the same solid volume, d_ve = d N^(1/3).
//
// Mobility-equivalent, free-molecular regime (primaries much smaller than the gas mean free path,
// 68 nm in air at 1 atm and 296 K, so 20 nm primaries and aggregates of up to a few hundred of
// them): the mobility diameter of a fractal aggregate equals its projected-area-equivalent
// diameter (Rogak, Flagan & Nguyen, Aerosol Sci. Technol. 18 (1993) 25; Sorensen, Aerosol Sci.
// Technol. 45 (2011) 765), and the projected area scales with N as N = k_a (d_a/d)^(2 D_alpha) with
// k_a = 1 and D_alpha = 1.08 (Eggersdorfer, Kadau, Herrmann & Pratsinis, J. Aerosol Sci. 46 (2012)
// 7; Eggersdorfer & Pratsinis, Aerosol Sci. Technol. 46 (2012) 347), so
// d_mob = d N^(1/(2 D_alpha)) = d N^0.463, close to Sorensen's N^0.46 for the free-molecular regime.
inline constexpr double kProjectedAreaExponent = 1.08;  // D_alpha
inline constexpr double kProjectedAreaPrefactor = 1.0;  // k_a

double volume_equivalent_diameter(double primaries);
double mobility_equivalent_diameter(double primaries);

}  // namespace aerobreak
