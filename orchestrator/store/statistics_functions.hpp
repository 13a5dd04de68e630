#pragma once
#include "orchestrator/store/sqlite_database.hpp"

namespace aerobreak {

// Adds to a connection the SQL aggregate squared_deviations(x): the sum of squared deviations of
// the non-null x from their mean, M2 = sum (x - mean)^2, by Welford's update (B. P. Welford,
// Technometrics 4 (1962) 419): for each x, n += 1, d = x - mean, mean += d / n, M2 += d (x - mean).
// In one pass like total(x * x), but without the cancellation of sum(x^2) - sum(x)^2 / n, which
// loses every digit of a variance that is small beside the squared mean. 0 without values.
void add_statistics_functions(SqliteDatabase& db);

}  // namespace aerobreak
