#include "orchestrator/cli/export_command.hpp"

#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <string>

#include "orchestrator/cli/exit_codes.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/service/study_tables.hpp"

namespace aerobreak {
namespace {

struct ExportOptions {
  std::string store;
  std::int64_t study = 0;
  std::string output;
  std::map<std::string, std::string> parameters;  // query parameter name -> value
};

// The options named as the REST query parameters (with '-' for '_').
constexpr const char* kParameters[][2] = {
    {"format", "csv | dat | json | hdf5 | melcor | openfoam [csv]"},
    {"kind", "grid | sections | fit [grid]"},
    {"youngs_modulus", "material: Young's modulus E, Pa (with the four below: SI columns)"},
    {"poisson_ratio", "material: Poisson ratio nu"},
    {"density", "material: density rho, kg/m^3"},
    {"surface_energy", "material: surface energy gamma, J/m^2 (per surface)"},
    {"diameter", "material: primary diameter d, m"},
    {"gamma_over_kn", "only the rows of this gamma/k_n (reduced units)"},
    {"interpolate", "gamma_over_kn: interpolate between the study's gamma/k_n values [none]"},
    {"section_ratio", "sections: mass ratio of a section's ends [2]"},
    {"quantity", "openfoam: p_stick | p_bounce | p_break_up | retained_mass_fraction | restitution [p_stick]"},
    {"layout", "openfoam: table2d | csv | dict [table2d]"},
    {"speeds", "fit: comma-separated impact speeds"},
    {"sizes", "fit: comma-separated cluster sizes (primaries)"},
    {"strict", "fit: true refuses rows outside the fit's validity box [false]"},
    {"select", "only the rows of one condition: NAME:VALUE[,NAME:VALUE], NAME an input column (e.g. wall_adhesive:1)"},
};

std::int64_t only_study(Store& store) {
  const auto studies = store.studies({2, 0});
  if (studies.total != 1)
    throw ExportError(400, "study", "the store holds " + std::to_string(studies.total) + " studies: choose one with --study");
  return studies.items.front().id;
}

void write_file(const std::filesystem::path& path, const std::string& content) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << content;
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

int run_export(const ExportOptions& options) {
  if (!std::filesystem::exists(options.store)) {
    std::cerr << "aerobreak export: no store file " << options.store << "\n";
    return kExitInvalidInput;
  }
  try {
    Store store(options.store, Store::Access::reader);
    const std::int64_t study = options.study > 0 ? options.study : only_study(store);
    const auto request = parse_export_request({options.parameters.begin(), options.parameters.end()});
    const auto record = store.study(study);
    if (!record) throw ExportError(404, "study", "no study " + std::to_string(study) + " in " + options.store);
    const auto rendered = render_table(export_lookup_table(store, *record, request), request, study);
    if (options.output == "-") {
      std::cout << rendered.content;
      return 0;
    }
    const std::filesystem::path path = std::filesystem::path(options.output.empty() ? rendered.file_name : options.output);
    write_file(path, rendered.content);
    std::cerr << "aerobreak export: wrote " << path.string() << "\n";
    return 0;
  } catch (const ExportError& error) {
    std::cerr << "aerobreak export: " << error.what() << (error.field.empty() ? "" : " [parameter " + error.field + "]") << "\n";
    return kExitInvalidInput;
  } catch (const std::runtime_error& error) {
    std::cerr << "aerobreak export: " << error.what() << "\n";
    return kExitError;
  }
}

}  // namespace

std::vector<std::filesystem::path> write_default_tables(Store& store, std::int64_t study_id,
                                                        const std::filesystem::path& directory) {
  const auto study = store.study(study_id);
  if (!study) throw ExportError(404, "study", "no study " + std::to_string(study_id));
  const std::map<TableKind, std::vector<TableFormat>> formats{
      {TableKind::grid, {TableFormat::csv, TableFormat::dat, TableFormat::json, TableFormat::hdf5, TableFormat::melcor}},
      {TableKind::sections, {TableFormat::csv, TableFormat::dat, TableFormat::json, TableFormat::hdf5}},
      {TableKind::fit, {TableFormat::csv, TableFormat::dat}}};
  std::vector<std::filesystem::path> written;
  for (const auto& [kind, kind_formats] : formats) {
    ExportRequest request;
    request.kind = kind;
    LookupTable table;
    try {
      table = export_lookup_table(store, *study, request);
    } catch (const ExportError& error) {
      if (kind == TableKind::fit) continue;  // a study without a fit in impact speed has no table (b)
      throw;
    }
    for (const auto format : kind_formats) {
      request.format = format;
      const auto rendered = render_table(table, request, study_id);
      written.push_back(directory / rendered.file_name);
      write_file(written.back(), rendered.content);
    }
  }
  return written;
}

void add_export_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ExportOptions>();
  auto* command = app.add_subcommand("export", "Write a study's lookup tables for system codes (docs/EXPORT.md)");
  command->add_option("--store", options->store, "SQLite store file")->required();
  command->add_option("--study", options->study, "Study id [default: the store's only study]")
      ->check(CLI::Range(std::int64_t{1}, std::numeric_limits<std::int64_t>::max()));
  command->add_option("-o,--output", options->output, "Output file ('-': stdout) [default: the table's file name, here]");
  for (const auto& [name, description] : kParameters) {
    std::string flag = std::string("--") + name;
    std::replace(flag.begin(), flag.end(), '_', '-');
    command->add_option_function<std::string>(
        flag, [options, key = std::string(name)](const std::string& value) { options->parameters[key] = value; }, description);
  }
  command->callback([options, &exit_code] {
    try {
      exit_code = run_export(*options);
    } catch (const std::exception& error) {
      std::cerr << "aerobreak export: " << error.what() << "\n";
      exit_code = kExitError;
    }
  });
}

}  // namespace aerobreak
