#pragma once
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "orchestrator/fitting/logistic_prediction.hpp"

// The fitted correlations as code a system code compiles (docs/EXPORT.md, "Correlations as code"):
// per condition and outcome a function P(v, n) with its 95 % band, a validity flag and the status
// of logistic_prediction.hpp, and the critical speed v_p(n) with its band, generated as a Fortran 90
// module and a C header, and described as JSON. The functions compute what predict and the
// delta-method critical dose compute, in the same order, so that they agree with the service.
namespace aerobreak {

// One condition's fit of one outcome, as the code evaluates it.
struct CodeFunction {
  std::string condition;         // c1, c2, ... (pooled over N) or g1, ... (one group's own fit)
  nlohmann::ordered_json group;  // the condition's axis values
  ImpactOutcome outcome = ImpactOutcome::break_up;
  std::string fit;  // the fit's name in the study's correlations ("" without one)
  PredictionSource source = PredictionSource::none;
  bool size_term = false;  // logit P = b0 + b1 ln v + b2 ln n (else b0 + b1 ln v)
  std::vector<double> coefficients;
  std::vector<std::vector<double>> covariance;
  std::array<double, 2> speed_box{0.0, 0.0};  // the validity box, as predict widens it (1e-12)
  std::array<double, 2> size_box{0.0, 0.0};
  BandPoint observed{};                 // a no-transition fit's 0 or 1 with its Wilson band
  std::vector<CriticalValue> critical;  // a group's own fit: its profile-likelihood values (constants)
};

struct CorrelationCode {
  std::int64_t study = 0;
  std::string prefix;               // "ab<study>_": of every name
  std::string speed_unit;           // "m/s" or "d/tau": the unit of v
  std::vector<std::string> header;  // comment lines: provenance, units, status codes
  std::vector<CodeFunction> functions;
};

// The code of a study's fits: per condition of the axes other than speed and N, the fits pooled
// over the sizes when the study sweeps N, else each group's own fits. `header` becomes the code's
// comment block. ExportError 409 when the study has no logistic fit in impact speed.
CorrelationCode correlation_code(const CorrelationSet& set, std::int64_t study, const std::string& speed_unit,
                                 std::vector<std::string> header);

std::string fortran_module(const CorrelationCode& code);
std::string c_header(const CorrelationCode& code);
nlohmann::ordered_json code_json(const CorrelationCode& code);

// The name of a generated function: ab<study>_<condition>_<p|v50>_<stick|bounce|breakup>.
std::string code_function_name(const CorrelationCode& code, const CodeFunction& function, const std::string& what);

}  // namespace aerobreak
