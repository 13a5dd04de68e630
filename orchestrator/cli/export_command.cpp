#include "orchestrator/cli/export_command.hpp"

#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <memory>
#include <string>

#include "orchestrator/cli/exit_codes.hpp"
#include "orchestrator/export/table_formats.hpp"
#include "orchestrator/app/study_tables.hpp"

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
    {"format", "csv | dat | json | hdf5 | melcor | openfoam; for kind correlations: fortran | c | json [csv]"},
    {"kind", "grid | sections | fit | correlations (the fits as code) [grid]"},
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
    {"diameters", "fit: comma-separated cluster diameters instead of sizes (m with SI, else d)"},
    {"diameter_type", "fit: mobility | volume | aerodynamic (m, SI only) [mobility]"},
    {"strict", "fit: true refuses rows outside the fit's validity box [false]"},
    {"select", "only the rows of one condition: NAME:VALUE[,NAME:VALUE], NAME an input column (e.g. wall_adhesive:1)"},
};

std::int64_t only_study(Store& store) {
  const auto studies = store.studies({2, 0});
  if (studies.total != 1)
    throw ExportError(400, "study",
                      "the store holds " + std::to_string(studies.total) + " studies: choose one with --study");
  return studies.items.front().id;
}

// A physical study's fit table at mobility diameters of 0.1, 0.3, 1 and 3 um (docs/EXPORT.md
// section 2), at the speeds of its grid: what a system code tracking a diameter reads.
std::optional<ExportRequest> mobility_diameter_request(const StudyRecord& study) {
  const nlohmann::ordered_json::json_pointer units("/base/units"), speeds("/axes/impact_speed/values");
  if (!study.document.contains(units) || study.document.at(units) != "physical") return std::nullopt;
  ExportRequest request;
  request.kind = TableKind::fit;
  request.diameters = {1e-7, 3e-7, 1e-6, 3e-6};
  if (study.document.contains(speeds))
    for (const auto& speed : study.document.at(speeds)) request.speeds.push_back(speed.get<double>());
  return request;
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
    StudyFits fits(store, StudyFits::Mode::read_only);  // the stored fits when current, else fitted in memory
    const std::int64_t study = options.study > 0 ? options.study : only_study(store);
    const auto request = parse_export_request({options.parameters.begin(), options.parameters.end()});
    const auto record = store.study(study);
    if (!record) throw ExportError(404, "study", "no study " + std::to_string(study) + " in " + options.store);
    const auto rendered = export_file(store, fits, *record, request);
    if (request.kind == TableKind::grid && record->document.contains("search"))
      std::cerr << "aerobreak export: note: " << kSearchedGridNote << "\n";
    if (options.output == "-") {
      std::cout << rendered.content;
      return 0;
    }
    const std::filesystem::path path =
        std::filesystem::path(options.output.empty() ? rendered.file_name : options.output);
    write_file(path, rendered.content);
    std::cerr << "aerobreak export: wrote " << path.string() << "\n";
    return 0;
  } catch (const ExportError& error) {
    std::cerr << "aerobreak export: " << error.what() << (error.field.empty() ? "" : " [parameter " + error.field + "]")
              << "\n";
    return kExitInvalidInput;
  } catch (const std::runtime_error& error) {
    std::cerr << "aerobreak export: " << error.what() << "\n";
    return kExitError;
  }
}

}  // namespace

std::vector<std::filesystem::path> write_default_tables(Store& store, StudyFits& fits, std::int64_t study_id,
                                                        const std::filesystem::path& directory) {
  const auto study = store.study(study_id);
  if (!study) throw ExportError(404, "study", "no study " + std::to_string(study_id));
  const std::vector<TableFormat> tables{TableFormat::csv, TableFormat::dat, TableFormat::json, TableFormat::hdf5,
                                        TableFormat::melcor};
  std::vector<std::pair<ExportRequest, std::vector<TableFormat>>> files;
  const auto add = [&files](ExportRequest request, std::vector<TableFormat> formats) {
    files.emplace_back(request, formats);
  };
  const auto of_kind = [](TableKind kind) {
    ExportRequest request;
    request.kind = kind;
    return request;
  };
  add(of_kind(TableKind::grid), tables);
  add(of_kind(TableKind::sections), {TableFormat::csv, TableFormat::dat, TableFormat::json, TableFormat::hdf5});
  add(of_kind(TableKind::fit), tables);
  if (const auto mobility = mobility_diameter_request(*study)) add(*mobility, tables);
  add(of_kind(TableKind::correlations), {TableFormat::fortran, TableFormat::c, TableFormat::json});
  std::vector<std::filesystem::path> written;
  for (auto& [request, formats] : files)
    for (const auto format : formats) {
      request.format = format;
      RenderedTable rendered;
      try {
        rendered = export_file(store, fits, *study, request);
      } catch (const ExportError& error) {
        if (request.kind == TableKind::fit || request.kind == TableKind::correlations) break;  // no fit in impact speed
        throw;
      }
      if (!request.diameters.empty()) rendered.file_name.insert(rendered.file_name.find("_fit") + 4, "_mobility");
      written.push_back(directory / rendered.file_name);
      write_file(written.back(), rendered.content);
    }
  return written;
}

void add_export_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ExportOptions>();
  auto* command = app.add_subcommand("export", "Write a study's lookup tables for system codes (docs/EXPORT.md)");
  command->add_option("--store", options->store, "SQLite store file")->required();
  command->add_option("--study", options->study, "Study id [default: the store's only study]")
      ->check(CLI::Range(std::int64_t{1}, std::numeric_limits<std::int64_t>::max()));
  command->add_option("-o,--output", options->output,
                      "Output file ('-': stdout) [default: the table's file name, here]");
  for (const auto& [name, description] : kParameters) {
    std::string flag = std::string("--") + name;
    std::replace(flag.begin(), flag.end(), '_', '-');
    command->add_option_function<std::string>(
        flag, [options, key = std::string(name)](const std::string& value) { options->parameters[key] = value; },
        description);
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
