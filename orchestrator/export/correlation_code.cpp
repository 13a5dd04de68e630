// The generated code of docs/EXPORT.md, "Correlations as code": which fits, and their Fortran 90,
// C and JSON forms. Every generated function repeats predict (logistic_prediction.hpp) or the
// delta-method critical dose (critical_dose.hpp) with the fit's numbers written to 17 digits.
#include "orchestrator/export/correlation_code.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>

#include "orchestrator/export/export_request.hpp"
#include "orchestrator/export/fit_blocks.hpp"
#include "orchestrator/export/lookup_table.hpp"

namespace aerobreak {
namespace {

constexpr double kWiden = 1e-12;  // predict's tolerance at the ends of a validity box

std::string outcome_word(ImpactOutcome outcome) {
  return outcome == ImpactOutcome::stick ? "stick" : outcome == ImpactOutcome::bounce ? "bounce" : "breakup";
}

// A double to 17 significant digits: read back, it is the same double. `exponent` 'd' for Fortran.
std::string literal(double value, char exponent = 'e') {
  char text[40];
  std::snprintf(text, sizeof text, "%.16e", value);
  std::string out = text;
  if (exponent != 'e') out[out.find('e')] = exponent;
  return out;
}

PredictionSource source_of(const LogisticFit& fit) {
  const bool fitted = fit.common.coefficients.size() == static_cast<Eigen::Index>(2 + fit.covariates.size());
  if (fit.common.status == FitStatus::ok && fitted) return PredictionSource::maximum_likelihood;
  if (fit.common.status == FitStatus::separation && fitted && fit.covariates.empty()) return PredictionSource::firth;
  if (fit.common.status == FitStatus::no_transition) return PredictionSource::no_transition;
  return PredictionSource::none;
}

std::array<double, 2> widened(const InputRange& range) {
  return {range.min * (1.0 - kWiden), range.max * (1.0 + kWiden)};
}

CodeFunction function_of(const LogisticFit& fit, const std::string& size_axis) {
  CodeFunction function;
  function.condition = fit.common.name.substr(fit.common.name.rfind('.') + 1);
  function.group = fit.common.group;
  function.outcome = fit.response;
  function.fit = fit.common.name;
  function.source = source_of(fit);
  function.size_term = !fit.covariates.empty();
  for (Eigen::Index i = 0; i < fit.common.coefficients.size(); ++i) {
    function.coefficients.push_back(fit.common.coefficients[i]);
    function.covariance.emplace_back();
    for (Eigen::Index j = 0; j < fit.common.covariance.cols(); ++j)
      function.covariance.back().push_back(fit.common.covariance(i, j));
  }
  function.size_box = {0.0, DBL_MAX};
  const double size = fit.common.group.value(size_axis, kMissing);
  if (!std::isnan(size)) function.size_box = widened({size_axis, size, size});
  for (const auto& range : fit.common.validity)
    (range.input == fit.dose ? function.speed_box : function.size_box) = widened(range);
  if (function.source == PredictionSource::no_transition) {
    Eigen::VectorXd covariates(static_cast<Eigen::Index>(fit.covariates.size()));
    for (Eigen::Index k = 0; k < covariates.size(); ++k)
      covariates[k] = fit.common.validity.at(static_cast<std::size_t>(k + 1)).min;
    function.observed = predict(fit, fit.common.validity[0].min, covariates).band;  // the same at every point
  }
  if (!function.size_term)
    for (const auto& value : fit.critical)
      if (value.level == 0.5) function.critical.push_back(value);
  return function;
}

std::string status_legend() {
  return "status: 0 fitted (maximum likelihood), 1 fitted under separation (Firth), 2 no transition in the fit's data "
         "(the observed 0 or 1, band the Wilson interval of its results), 3 no value (p, lo, hi = the missing value)";
}

// A probability function has coefficients to evaluate (otherwise a constant or the missing value).
bool is_fitted(const CodeFunction& f) {
  return f.source == PredictionSource::maximum_likelihood || f.source == PredictionSource::firth;
}

// A v50 at one size, with both ends of its interval: the constant a function without a size term returns.
bool has_single_size_v50(const CodeFunction& f) {
  return is_fitted(f) && !f.critical.empty() && f.critical[0].estimate && f.critical[0].lower && f.critical[0].upper;
}

// The words above each function, in either language.
std::string probability_description(const CorrelationCode& code, const CodeFunction& f) {
  return "P(" + std::string(to_string(f.outcome)) + ") on condition " + f.condition + " (" + f.group.dump() +
         "), fit " + (f.fit.empty() ? "none" : f.fit) + ": v impact speed [" + code.speed_unit +
         "], n primaries; validity box v in [" + literal(f.speed_box[0]) + ", " + literal(f.speed_box[1]) +
         "], n in [" + literal(f.size_box[0]) + ", " + literal(f.size_box[1]) + "]";
}

std::string v50_description(const CorrelationCode& code, const CodeFunction& f) {
  return "v50 of " + std::string(to_string(f.outcome)) + " [" + code.speed_unit + "] on condition " + f.condition +
         " at n primaries, 95 % interval " +
         (f.size_term ? "by the delta method" : "by profile likelihood (this size only)");
}

// --- Fortran 90 ---------------------------------------------------------------------------------

// The output arguments every Fortran function shares.
const char* const kFortranOutputs =
    "    real(dp), intent(out) :: lo, hi\n    logical, intent(out) :: inside\n    integer, intent(out) :: status\n";

std::string fortran_comment(const std::string& text, const std::string& indent = "  ") {
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {  // lines of at most 100 characters, split at spaces
    std::size_t end = std::min(text.size(), start + 96);
    if (end < text.size()) {
      const auto space = text.rfind(' ', end);
      if (space != std::string::npos && space > start) end = space;
    }
    out += indent + "! " + text.substr(start, end - start) + "\n";
    start = end + (end < text.size() && text[end] == ' ' ? 1 : 0);
  }
  return out;
}

// Free-form lines stay within 132 characters: three values per line, continued with '&'.
std::string fortran_array(const std::vector<double>& values) {
  std::string text = "&\n      ";
  for (std::size_t i = 0; i < values.size(); ++i)
    text += literal(values[i], 'd') + (i + 1 == values.size() ? "" : i % 3 == 2 ? ", &\n      " : ", ");
  return text;
}

// Column-major, as Fortran's reshape fills a matrix.
std::vector<double> column_major(const std::vector<std::vector<double>>& matrix) {
  std::vector<double> values;
  for (std::size_t j = 0; j < matrix.size(); ++j)
    for (std::size_t i = 0; i < matrix.size(); ++i) values.push_back(matrix[i][j]);
  return values;
}

std::string fortran_inside(const CodeFunction& f, const std::string& speed) {
  return "    inside = " + speed + " >= " + literal(f.speed_box[0], 'd') + " .and. " + speed +
         " <= " + literal(f.speed_box[1], 'd') + " &\n      .and. n >= " + literal(f.size_box[0], 'd') +
         " .and. n <= " + literal(f.size_box[1], 'd') + "\n";
}

std::string fortran_parameters(const CodeFunction& f) {
  const std::string k = std::to_string(f.coefficients.size());
  return "    real(dp), parameter :: b(" + k + ") = [" + fortran_array(f.coefficients) + "]\n" +
         "    real(dp), parameter :: cov(" + k + ", " + k + ") = reshape([" +
         fortran_array(column_major(f.covariance)) + "], [" + k + ", " + k + "])\n";
}

std::string fortran_probability(const CorrelationCode& code, const CodeFunction& f) {
  const std::string name = code_function_name(code, f, "p");
  std::string text = "\n" + fortran_comment(probability_description(code, f)) + "  function " + name +
                     "(v, n, lo, hi, inside, status) result(p)\n    real(dp), intent(in) :: v, n\n" + kFortranOutputs +
                     "    real(dp) :: p\n";
  const bool fitted = is_fitted(f);
  if (fitted) text += fortran_parameters(f);
  text += fortran_inside(f, "v") + "    status = " + std::to_string(static_cast<int>(f.source)) + "\n";
  if (fitted)
    text += std::string("    call ") + code.prefix + "band(b, cov, [1.0_dp, log(v)" + (f.size_term ? ", log(n)" : "") +
            "], p, lo, hi)\n";
  else if (f.source == PredictionSource::no_transition)
    text += "    p = " + literal(f.observed.probability, 'd') + "\n    lo = " + literal(f.observed.lower, 'd') +
            "\n    hi = " + literal(f.observed.upper, 'd') + "\n";
  else
    text += "    p = " + code.prefix + "missing\n    lo = " + code.prefix + "missing\n    hi = " + code.prefix +
            "missing\n";
  return text + "  end function " + name + "\n";
}

std::string fortran_v50(const CorrelationCode& code, const CodeFunction& f) {
  const std::string name = code_function_name(code, f, "v50");
  std::string text = "\n" + fortran_comment(v50_description(code, f)) + "  function " + name +
                     "(n, lo, hi, inside, status) result(v)\n    real(dp), intent(in) :: n\n" + kFortranOutputs +
                     "    real(dp) :: v\n";
  if (is_fitted(f) && f.size_term) {
    text += fortran_parameters(f) + "    call " + code.prefix + "critical(b, cov, 0.5_dp, n, v, lo, hi)\n";
  } else if (has_single_size_v50(f)) {
    text += "    v = " + literal(*f.critical[0].estimate, 'd') + "\n    lo = " + literal(*f.critical[0].lower, 'd') +
            "\n    hi = " + literal(*f.critical[0].upper, 'd') + "\n";
  } else {
    return text + "    v = " + code.prefix + "missing\n    lo = " + code.prefix + "missing\n    hi = " + code.prefix +
           "missing\n    inside = n >= " + literal(f.size_box[0], 'd') + " .and. n <= " + literal(f.size_box[1], 'd') +
           "\n    status = 3\n  end function " + name + "\n";
  }
  return text + fortran_inside(f, "v") + "    status = " + std::to_string(static_cast<int>(f.source)) +
         "\n  end function " + name + "\n";
}

// --- C ------------------------------------------------------------------------------------------

std::string c_comment(const std::string& text) { return "/* " + text + " */\n"; }

std::string c_array(const std::vector<double>& values) {
  std::string text;
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + literal(values[i]);
  return text;
}

std::vector<double> row_major(const std::vector<std::vector<double>>& matrix) {
  std::vector<double> values;
  for (const auto& row : matrix) values.insert(values.end(), row.begin(), row.end());
  return values;
}

std::string c_inside(const CodeFunction& f, const std::string& speed) {
  return "  *inside = " + speed + " >= " + literal(f.speed_box[0]) + " && " + speed + " <= " + literal(f.speed_box[1]) +
         " && n >= " + literal(f.size_box[0]) + " && n <= " + literal(f.size_box[1]) + ";\n";
}

std::string c_parameters(const CodeFunction& f) {
  const std::string k = std::to_string(f.coefficients.size());
  return "  static const double b[" + k + "] = {" + c_array(f.coefficients) + "};\n  static const double cov[" + k +
         " * " + k + "] = {" + c_array(row_major(f.covariance)) + "};\n";
}

// The missing value's macro name in the C header.
std::string c_missing(const CorrelationCode& code) { return "AB" + std::to_string(code.study) + "_MISSING"; }

std::string c_probability(const CorrelationCode& code, const CodeFunction& f) {
  const std::string name = code_function_name(code, f, "p");
  std::string text = "\n" + c_comment(probability_description(code, f)) + "static inline double " + name +
                     "(double v, double n, double *lo, double *hi, int *inside, int *status) {\n";
  const bool fitted = is_fitted(f);
  if (fitted) text += c_parameters(f);
  text += c_inside(f, "v") + "  *status = " + std::to_string(static_cast<int>(f.source)) + ";\n";
  if (fitted) {
    text += "  const double x[" + std::to_string(f.coefficients.size()) + "] = {1.0, log(v)" +
            (f.size_term ? ", log(n)" : "") + "};\n  double p;\n";
    if (!f.size_term) text += "  (void)n;\n";
    text += "  " + code.prefix + "band(b, cov, x, " + std::to_string(f.coefficients.size()) +
            ", &p, lo, hi);\n  return p;\n}\n";
    return text;
  }
  if (f.source == PredictionSource::no_transition)
    return text + "  *lo = " + literal(f.observed.lower) + ";\n  *hi = " + literal(f.observed.upper) + ";\n  return " +
           literal(f.observed.probability) + ";\n}\n";
  const std::string missing = c_missing(code);
  return text + "  *lo = " + missing + ";\n  *hi = " + missing + ";\n  return " + missing + ";\n}\n";
}

std::string c_v50(const CorrelationCode& code, const CodeFunction& f) {
  const std::string name = code_function_name(code, f, "v50");
  std::string text = "\n" + c_comment(v50_description(code, f)) + "static inline double " + name +
                     "(double n, double *lo, double *hi, int *inside, int *status) {\n  double v;\n";
  const std::string missing = c_missing(code);
  if (is_fitted(f) && f.size_term) {
    text += c_parameters(f) + "  " + code.prefix + "critical(b, cov, 0.5, n, &v, lo, hi);\n";
  } else if (has_single_size_v50(f)) {
    text += "  v = " + literal(*f.critical[0].estimate) + ";\n  *lo = " + literal(*f.critical[0].lower) +
            ";\n  *hi = " + literal(*f.critical[0].upper) + ";\n";
  } else {
    return text + "  v = " + missing + ";\n  *lo = " + missing + ";\n  *hi = " + missing +
           ";\n  *inside = n >= " + literal(f.size_box[0]) + " && n <= " + literal(f.size_box[1]) +
           ";\n  *status = 3;\n  return v;\n}\n";
  }
  return text + c_inside(f, "v") + "  *status = " + std::to_string(static_cast<int>(f.source)) + ";\n  return v;\n}\n";
}

}  // namespace

std::string code_function_name(const CorrelationCode& code, const CodeFunction& function, const std::string& what) {
  return code.prefix + function.condition + "_" + what + "_" + outcome_word(function.outcome);
}

CorrelationCode correlation_code(const CorrelationSet& set, std::int64_t study, const std::string& speed_unit,
                                 std::vector<std::string> header) {
  CorrelationCode code;
  code.study = study;
  code.prefix = "ab" + std::to_string(study) + "_";
  code.speed_unit = speed_unit;
  code.header = std::move(header);
  code.header.push_back(status_legend());
  const std::string size_axis = size_axis_of(set);
  const bool pooled = std::any_of(set.logistic.begin(), set.logistic.end(),
                                  [&](const LogisticFit& fit) { return pooled_over_size(fit, size_axis); });
  for (const auto& fit : set.logistic)
    if (fit.dose == "impact_speed" && (pooled ? pooled_over_size(fit, size_axis) : fit.covariates.empty()))
      code.functions.push_back(function_of(fit, size_axis));
  if (code.functions.empty())
    throw ExportError(409, "kind", "the study has no logistic fit of an outcome in impact speed");
  return code;
}

std::string fortran_module(const CorrelationCode& code) {
  const std::string& x = code.prefix;
  std::string text = "! Generated by aerobreak (docs/EXPORT.md, \"Correlations as code\"): Fortran 90.\n";
  for (const auto& line : code.header) text += fortran_comment(line, "");
  text += "module aerobreak_study" + std::to_string(code.study) +
          "\n  implicit none\n  private\n"
          "  integer, parameter :: dp = kind(1.0d0)\n  real(dp), parameter, public :: " +
          x + "missing = -1.0d30\n";
  for (const auto& f : code.functions)
    text += "  public :: " + code_function_name(code, f, "p") + ", " + code_function_name(code, f, "v50") + "\n";
  text +=
      "contains\n\n  ! 1 / (1 + exp(-t)), without overflow\n  pure function " + x +
      "logistic(t) result(p)\n"
      "    real(dp), intent(in) :: t\n    real(dp) :: p\n    if (t >= 0.0_dp) then\n      p = 1.0_dp / (1.0_dp + "
      "exp(-t))\n"
      "    else\n      p = exp(t) / (1.0_dp + exp(t))\n    end if\n  end function " +
      x +
      "logistic\n\n"
      "  ! P = logistic(x'b) and its 95 % band logistic(x'b -+ 1.959963984540054 sqrt(x' cov x))\n"
      "  subroutine " +
      x +
      "band(b, cov, x, p, lo, hi)\n    real(dp), intent(in) :: b(:), cov(:, :), x(:)\n"
      "    real(dp), intent(out) :: p, lo, hi\n    real(dp) :: eta, variance, half\n    integer :: i, j\n"
      "    eta = 0.0_dp\n    variance = 0.0_dp\n    do i = 1, size(b)\n      eta = eta + x(i) * b(i)\n"
      "      do j = 1, size(b)\n        variance = variance + x(i) * cov(i, j) * x(j)\n      end do\n    end do\n"
      "    half = 1.959963984540054_dp * sqrt(max(0.0_dp, variance))\n    p = " +
      x +
      "logistic(eta)\n"
      "    lo = " +
      x + "logistic(eta - half)\n    hi = " + x + "logistic(eta + half)\n  end subroutine " + x +
      "band\n\n"
      "  ! The speed where logit P = b1 + b2 ln v + b3 ln n crosses `level`, with the delta-method 95 % interval\n"
      "  subroutine " +
      x +
      "critical(b, cov, level, n, v, lo, hi)\n    real(dp), intent(in) :: b(3), cov(3, 3), level, n\n"
      "    real(dp), intent(out) :: v, lo, hi\n    real(dp) :: theta, g(3), variance, half\n    integer :: i, j\n"
      "    theta = (log(level / (1.0_dp - level)) - b(1) - log(n) * b(3)) / b(2)\n"
      "    g = [-1.0_dp / b(2), -theta / b(2), -log(n) / b(2)]\n    variance = 0.0_dp\n    do i = 1, 3\n"
      "      do j = 1, 3\n        variance = variance + g(i) * cov(i, j) * g(j)\n      end do\n    end do\n"
      "    half = 1.959963984540054_dp * sqrt(max(0.0_dp, variance))\n    v = exp(theta)\n    lo = exp(theta - half)\n"
      "    hi = exp(theta + half)\n  end subroutine " +
      x + "critical\n";
  for (const auto& f : code.functions) text += fortran_probability(code, f) + fortran_v50(code, f);
  return text + "\nend module aerobreak_study" + std::to_string(code.study) + "\n";
}

std::string c_header(const CorrelationCode& code) {
  const std::string& x = code.prefix;
  const std::string guard = "AEROBREAK_STUDY" + std::to_string(code.study) + "_H";
  std::string text = "/* Generated by aerobreak (docs/EXPORT.md, \"Correlations as code\"): a C99 header. */\n";
  for (const auto& line : code.header) text += c_comment(line);
  text +=
      "#ifndef " + guard + "\n#define " + guard + "\n#include <math.h>\n\n#define " + c_missing(code) +
      " (-1.0e30)\n\n/* 1 / (1 + exp(-t)), without overflow */\nstatic inline double " + x +
      "logistic(double t) {\n"
      "  if (t >= 0.0) return 1.0 / (1.0 + exp(-t));\n  return exp(t) / (1.0 + exp(t));\n}\n\n"
      "/* P = logistic(x'b) and its 95 % band logistic(x'b -+ 1.959963984540054 sqrt(x' cov x)); cov row-major */\n"
      "static inline void " +
      x +
      "band(const double *b, const double *cov, const double *x, int k, double *p, double *lo,\n"
      "                             double *hi) {\n  double eta = 0.0, variance = 0.0, half;\n  int i, j;\n"
      "  for (i = 0; i < k; ++i) {\n    eta += x[i] * b[i];\n    for (j = 0; j < k; ++j) variance += x[i] * cov[i * k "
      "+ j] * x[j];\n"
      "  }\n  half = 1.959963984540054 * sqrt(variance > 0.0 ? variance : 0.0);\n  *p = " +
      x +
      "logistic(eta);\n"
      "  *lo = " +
      x + "logistic(eta - half);\n  *hi = " + x +
      "logistic(eta + half);\n}\n\n"
      "/* The speed where logit P = b0 + b1 ln v + b2 ln n crosses `level`, with the delta-method 95 % interval */\n"
      "static inline void " +
      x +
      "critical(const double *b, const double *cov, double level, double n, double *v, double *lo,\n"
      "                                 double *hi) {\n"
      "  const double theta = (log(level / (1.0 - level)) - b[0] - log(n) * b[2]) / b[1];\n"
      "  const double g[3] = {-1.0 / b[1], -theta / b[1], -log(n) / b[1]};\n  double variance = 0.0, half;\n  int i, "
      "j;\n"
      "  for (i = 0; i < 3; ++i)\n    for (j = 0; j < 3; ++j) variance += g[i] * cov[i * 3 + j] * g[j];\n"
      "  half = 1.959963984540054 * sqrt(variance > 0.0 ? variance : 0.0);\n  *v = exp(theta);\n  *lo = exp(theta - "
      "half);\n"
      "  *hi = exp(theta + half);\n}\n";
  for (const auto& f : code.functions) text += c_probability(code, f) + c_v50(code, f);
  return text + "\n#endif\n";
}

nlohmann::ordered_json code_json(const CorrelationCode& code) {
  nlohmann::ordered_json functions = nlohmann::ordered_json::array();
  for (const auto& f : code.functions) {
    nlohmann::ordered_json entry{
        {"p", code_function_name(code, f, "p")},
        {"v50", code_function_name(code, f, "v50")},
        {"condition", f.condition},
        {"group", f.group},
        {"outcome", std::string(to_string(f.outcome))},
        {"fit", f.fit},
        {"status", static_cast<int>(f.source)},
        {"terms", f.size_term ? nlohmann::ordered_json{"1", "ln(v)", "ln(n)"} : nlohmann::ordered_json{"1", "ln(v)"}},
        {"coefficients", f.coefficients},
        {"covariance", f.covariance},
        {"validity", {{"v", f.speed_box}, {"n", f.size_box}}}};
    if (f.source == PredictionSource::no_transition)
      entry["observed"] = {{"p", f.observed.probability}, {"lo", f.observed.lower}, {"hi", f.observed.upper}};
    functions.push_back(entry);
  }
  return {{"format", "aerobreak-correlation-code"},
          {"format_version", 1},
          {"study", code.study},
          {"units", {{"v", code.speed_unit}, {"n", "primaries"}}},
          {"model",
           "logit P = x'b, x = terms; 95 % band logistic(x'b -+ 1.959963984540054 sqrt(x' covariance x)); v50 where "
           "P = 0.5, delta-method interval (docs/EXPORT.md)"},
          {"header", code.header},
          {"functions", functions}};
}

}  // namespace aerobreak
