// Thermal conditions of Brownian growth: the JKR bond energy against its closed form, and the
// temperature, drag and diffusion coefficient that follow from E_b / kT and l_p.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/core/units.hpp"
#include "engine/growth/brownian_conditions.hpp"

using namespace aerobreak;

TEST_CASE("the JKR bond energy is 1.5425 F_c delta_c whatever gamma / k_n") {
  // U = 4 F_c (a0^2/R*) [P(x) - P(x_touch)], P = (2/5)x^5 - (2/3)x^(7/2) + x^2/6, a0^2/R* =
  // 2 6^(1/3) delta_c (eqs 2-5): U(x = 1) = -0.60706 F_c delta_c at equilibrium and U = +0.93546
  // F_c delta_c at delta = -delta_c, where x = 6^(-2/3).
  for (double gamma : {0.001, 0.01, 0.05}) {
    const Material material = reduced_material(gamma, 0.3);
    const ContactModelSpec model;
    const ContactConstants c = primary_contact(material, model, 1.0, 1.0);
    const BrownianConditions b = brownian_conditions(material, model, 1.0, 1.0, 100.0, 1.0);
    INFO("gamma/k_n = " << gamma);
    CHECK(b.bond_energy == Approx(1.54252 * c.pull_off_force * c.critical_overlap).epsilon(1e-4));
    CHECK(b.temperature == Approx(b.bond_energy / 100.0));
  }
}

TEST_CASE("drag and diffusion follow from the persistence length") {
  const Material material = reduced_material(0.01, 0.3);
  const BrownianConditions b = brownian_conditions(material, ContactModelSpec{}, 1.0, 1.0, 20.0, 0.5);
  CHECK(b.thermal_speed == Approx(std::sqrt(b.temperature)));
  // l_p = v_th m / zeta, D = kT / zeta = v_th l_p (Stokes-Einstein).
  CHECK(b.thermal_speed / b.drag == Approx(0.5));
  CHECK(b.drag_per_diameter == Approx(b.drag));
  CHECK(b.diffusion == Approx(b.thermal_speed * 0.5));
}

TEST_CASE("brownian conditions reject a law without adhesion and non-positive inputs") {
  const Material material = reduced_material(0.01, 0.3);
  ContactModelSpec hertz;
  hertz.normal = NormalLaw::hertz;
  CHECK_THROWS_AS(brownian_conditions(material, hertz, 1.0, 1.0, 100.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(brownian_conditions(material, ContactModelSpec{}, 1.0, 1.0, 0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(brownian_conditions(material, ContactModelSpec{}, 1.0, 1.0, 100.0, -1.0), std::invalid_argument);
}
