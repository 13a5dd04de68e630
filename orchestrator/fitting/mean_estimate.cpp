#include "orchestrator/fitting/mean_estimate.hpp"

#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace aerobreak {
namespace {

// R 4.2: cat(sprintf("%.17g", qt(0.975, 1:30)), sep = ", ").
constexpr std::array<double, 30> kStudentT975{
    12.706204736174694, 4.3026527297494619, 3.1824463052837078, 2.7764451051977934, 2.5705818356363137,
    2.4469118511449688, 2.3646242515927844, 2.3060041352041658, 2.2621571627982049, 2.2281388519862739,
    2.2009851600916388, 2.1788128296672284, 2.1603686564627917, 2.1447866879178039, 2.1314495455597751,
    2.1199052992212541, 2.1098155778333165, 2.1009220402410382, 2.0930240544083092, 2.0859634472658648,
    2.07961384472768,   2.0738730679040258, 2.0686576104190482, 2.0638985616280254, 2.0595385527532977,
    2.0555294386428726, 2.051830516480285,  2.0484071417952445, 2.0452296421327034, 2.0422724563012378};

}  // namespace

double student_t_975(std::size_t degrees_of_freedom) {
  if (degrees_of_freedom == 0) throw std::invalid_argument("Student's t needs at least one degree of freedom");
  if (degrees_of_freedom <= kStudentT975.size()) return kStudentT975[degrees_of_freedom - 1];
  // A&S 26.7.5: t = z + g1/nu + g2/nu^2 + g3/nu^3 + g4/nu^4, z the normal quantile.
  const double z = kZ95;
  const double z2 = z * z;
  const double g1 = (z2 + 1.0) * z / 4.0;
  const double g2 = ((5.0 * z2 + 16.0) * z2 + 3.0) * z / 96.0;
  const double g3 = (((3.0 * z2 + 19.0) * z2 + 17.0) * z2 - 15.0) * z / 384.0;
  const double g4 = ((((79.0 * z2 + 776.0) * z2 + 1482.0) * z2 - 1920.0) * z2 - 945.0) * z / 92160.0;
  const double nu = static_cast<double>(degrees_of_freedom);
  return z + (g1 + (g2 + (g3 + g4 / nu) / nu) / nu) / nu;
}

MeanEstimate mean_with_interval(std::size_t count, double mean, double variance) {
  MeanEstimate estimate{count, mean, std::nullopt, std::nullopt, std::nullopt, std::nullopt};
  if (count < 2) return estimate;
  const double standard_error = std::sqrt(variance / static_cast<double>(count));
  const double half_width = student_t_975(count - 1) * standard_error;
  estimate.standard_deviation = std::sqrt(variance);
  estimate.standard_error = standard_error;
  estimate.lower = mean - half_width;
  estimate.upper = mean + half_width;
  return estimate;
}

std::optional<MeanEstimate> mean_estimate(std::span<const double> values) {
  if (values.empty()) return std::nullopt;
  const double sum = std::accumulate(values.begin(), values.end(), 0.0);
  const double mean = sum / static_cast<double>(values.size());
  double squares = 0.0;
  for (const double value : values) squares += (value - mean) * (value - mean);
  return streamed_mean_estimate(values.size(), sum, squares);
}

std::optional<MeanEstimate> streamed_mean_estimate(std::size_t count, double sum, double squared_deviations) {
  if (count == 0) return std::nullopt;
  const double n = static_cast<double>(count);
  return mean_with_interval(count, sum / n, count > 1 ? squared_deviations / (n - 1.0) : 0.0);
}

std::optional<MeanEstimate> ratio_estimate(std::span<const double> numerators, std::span<const double> denominators) {
  if (numerators.size() != denominators.size()) throw std::invalid_argument("ratio estimate: unequal lengths");
  const double a = std::accumulate(numerators.begin(), numerators.end(), 0.0);
  const double b = std::accumulate(denominators.begin(), denominators.end(), 0.0);
  if (numerators.empty() || b <= 0.0) return std::nullopt;
  const double ratio = a / b;
  const double n = static_cast<double>(numerators.size());
  if (numerators.size() < 2) return mean_with_interval(1, ratio, 0.0);
  double squares = 0.0;
  for (std::size_t i = 0; i < numerators.size(); ++i) {
    const double residual = numerators[i] - ratio * denominators[i];
    squares += residual * residual;
  }
  const double mean_b = b / n;
  return mean_with_interval(numerators.size(), ratio, squares / (n - 1.0) / (mean_b * mean_b));
}

}  // namespace aerobreak
