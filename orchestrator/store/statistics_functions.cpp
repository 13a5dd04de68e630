#include "orchestrator/store/statistics_functions.hpp"

namespace aerobreak {
namespace {

struct WelfordState {
  sqlite3_int64 count;
  double mean;
  double squared_deviations;
};

void welford_step(sqlite3_context* context, int, sqlite3_value** arguments) {
  if (sqlite3_value_type(arguments[0]) == SQLITE_NULL) return;
  // Zeroed by SQLite on the first call of a group.
  auto* state = static_cast<WelfordState*>(sqlite3_aggregate_context(context, sizeof(WelfordState)));
  if (!state) {
    sqlite3_result_error_nomem(context);
    return;
  }
  const double x = sqlite3_value_double(arguments[0]);
  ++state->count;
  const double deviation = x - state->mean;
  state->mean += deviation / static_cast<double>(state->count);
  state->squared_deviations += deviation * (x - state->mean);
}

void welford_final(sqlite3_context* context) {
  const auto* state = static_cast<WelfordState*>(sqlite3_aggregate_context(context, 0));
  sqlite3_result_double(context, state ? state->squared_deviations : 0.0);
}

}  // namespace

void add_statistics_functions(SqliteDatabase& db) {
  const int code = sqlite3_create_function_v2(db.handle(), "squared_deviations", 1,
                                              SQLITE_UTF8 | SQLITE_DETERMINISTIC | SQLITE_INNOCUOUS, nullptr, nullptr,
                                              welford_step, welford_final, nullptr);
  if (code != SQLITE_OK)
    throw SqliteError("SQLite: cannot add squared_deviations: " + std::string(sqlite3_errmsg(db.handle())), code);
}

}  // namespace aerobreak
