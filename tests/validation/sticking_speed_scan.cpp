// The monomer-wall sticking speed against the primary diameter in physical units (docs/STUDIES.md
// section 3): for each diameter from 10 nm to 1 um, the speed found by bisection with the impact
// pipeline at the automatic step, the closed form, their ratio, and the fitted log-log slope,
// which dimensional analysis of the JKR loss fixes at -5/6.
//   build/tests/validation/sticking_speed_scan [E_Pa nu rho_kg_m3 gamma_J_m2]
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "tests/validation/monomer_sticking.hpp"

int main(int argc, char** argv) {
  aerobreak::validation::MaterialSI material;
  if (argc == 5) {
    material = {std::atof(argv[1]), std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4])};
  } else if (argc != 1) {
    std::fprintf(stderr, "usage: %s [E_Pa nu rho_kg_m3 gamma_J_m2]\n", argv[0]);
    return 2;
  }
  std::printf("# E = %g Pa, nu = %g, rho = %g kg/m^3, gamma = %g J/m^2; undamped, head-on, automatic step\n",
              material.youngs_modulus, material.poisson_ratio, material.density, material.surface_energy);
  std::printf("d_m,v_stick_m_s,v_exact_m_s,ratio\n");
  std::vector<double> diameters, speeds;
  for (double d : {10e-9, 20e-9, 50e-9, 100e-9, 200e-9, 500e-9, 1000e-9}) {
    const double v = aerobreak::validation::monomer_sticking_speed(material, d);
    const double exact = aerobreak::validation::exact_monomer_sticking_speed(material, d);
    std::printf("%.3g,%.6g,%.6g,%.5f\n", d, v, exact, v / exact);
    diameters.push_back(d);
    speeds.push_back(v);
  }
  std::printf("# fitted slope d ln v / d ln d = %.5f (dimensional analysis: -5/6 = %.5f)\n",
              aerobreak::validation::log_log_slope(diameters, speeds), -5.0 / 6.0);
  return 0;
}
