#pragma once
#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "orchestrator/app/study_fits.hpp"
#include "orchestrator/store/store.hpp"

namespace aerobreak {

// `aerobreak export`: a study's lookup tables for system codes (docs/EXPORT.md) from a store file,
// with the parameters of GET /api/studies/ID/tables as options. Exit status 0, 1 when the store
// or the study cannot be read, 2 for a request the study cannot serve (the message names the
// parameter).
void add_export_command(CLI::App& app, int& exit_code);

// Writes a study's lookup tables into `directory` (docs/EXPORT.md): grid and fit (when the study
// has fits in impact speed) as CSV, .dat, JSON, HDF5 and MELCOR tabular functions, for a physical
// study the fit table at mobility diameters of 0.1-3 um too (studyID_fit_mobility.*), sections as
// CSV, .dat, JSON and HDF5, and the fitted correlations as a Fortran module, a C header and JSON; returns
// the files written. What `aerobreak run` leaves after a study; the fit table and the code read the
// study's stored fits (`fits`), fitted only if the store has none of its current result set.
std::vector<std::filesystem::path> write_default_tables(Store& store, StudyFits& fits, std::int64_t study_id,
                                                        const std::filesystem::path& directory);

}  // namespace aerobreak
