#pragma once
// A seeded synthetic outcome law with known crossings: the engine's test double for the adaptive
// search (docs/ADAPTIVE.md, "Validation"). P(break-up | v) = L((ln v - ln v_b) / s) and
// P(stick | v) = 1 - L((ln v - ln v_s) / s), L the logistic function, v_s < v_b, bounce in between;
// both crossing speeds scale as (gamma/k_n / 0.001)^exponent, so that groups differ.
#include <cmath>
#include <cstdint>
#include <string>

namespace aerobreak::testing {

struct SyntheticLaw {
  double break_up_speed = 0.05;  // P(break-up) = 0.5 here at gamma/k_n = 0.001 (d/tau)
  double stick_speed = 0.02;     // P(stick) = 0.5 here
  double spread = 0.25;          // logistic scale in ln v
  double gamma_exponent = 0.5;

  double scale(double gamma_over_kn) const { return std::pow(gamma_over_kn / 0.001, gamma_exponent); }

  // The speed where P(response) = level.
  double crossing(const std::string& response, double level, double gamma_over_kn = 0.001) const {
    const double logit = std::log(level / (1.0 - level));
    if (response == "break-up") return break_up_speed * scale(gamma_over_kn) * std::exp(spread * logit);
    return stick_speed * scale(gamma_over_kn) * std::exp(-spread * logit);  // stick
  }

  // The outcome of a case whose uniform draw is u in [0, 1): one latent draw decides all three
  // classes, so that P(not stick) >= P(break-up) at every speed.
  std::string outcome(double speed, double gamma_over_kn, double u) const {
    const double x = std::log(speed / scale(gamma_over_kn));
    const double p_break = 1.0 / (1.0 + std::exp(-(x - std::log(break_up_speed)) / spread));
    const double p_not_stick = 1.0 / (1.0 + std::exp(-(x - std::log(stick_speed)) / spread));
    if (u < p_break) return "break-up";
    if (u < p_not_stick) return "bounce";
    return "stick";
  }
};

// A uniform draw in [0, 1) from two seeds (splitmix64 finaliser).
inline double uniform_from_seeds(std::uint64_t a, std::uint64_t b) {
  std::uint64_t z = a * 0x9e3779b97f4a7c15ULL ^ (b + 0x632be59bd9b4e019ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

}  // namespace aerobreak::testing
