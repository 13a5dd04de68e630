#include "orchestrator/cli/study_expand_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "orchestrator/cli/exit_codes.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {
namespace {

struct ExpandOptions {
  std::string study_file;
  bool json = false;
};

void print_table(const Study& study, const std::vector<StudyCase>& cases) {
  std::cout << study.name << ": " << cases.size() << " case" << (cases.size() == 1 ? "" : "s") << " (study "
            << study.hash.substr(0, 12) << ")\n";
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const StudyCase& c = cases[k];
    std::printf("%6zu  %s  %s  replicate %d\n", k, c.hash.substr(0, 12).c_str(), c.grid_key.c_str(), c.replicate);
  }
}

void print_json(const std::vector<StudyCase>& cases) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& c : cases)
    out.push_back(
        {{"hash", c.hash}, {"grid_point", c.grid_point}, {"replicate", c.replicate}, {"document", c.document}});
  std::cout << out.dump(2) << "\n";
}

void expand(const ExpandOptions& o) {
  try {
    const Study study = load_study(o.study_file);
    const std::vector<StudyCase> cases = study.cases;
    if (o.json)
      print_json(cases);
    else
      print_table(study, cases);
  } catch (const StudyError& e) {
    std::cerr << "aerobreak study expand: invalid study " << o.study_file << ":\n";
    for (const auto& v : e.violations())
      std::cerr << "  " << (v.pointer.empty() ? std::string("(document)") : v.pointer) << ": " << v.message << "\n";
    // CLI11's way for a callback to end the program with a status of its own.
    throw CLI::RuntimeError(kExitInvalidInput);
  }
}

}  // namespace

void add_study_expand_subcommand(CLI::App& study) {
  auto options = std::make_shared<ExpandOptions>();
  auto* expand_command = study.add_subcommand(
      "expand", "Check a study file (schemas/study.schema.json) and list its cases offline, without a service");
  expand_command->add_option("study", options->study_file, "Study file (JSON, schemas/study.schema.json)")->required();
  expand_command->add_flag("--json", options->json,
                           "Print the cases as a JSON array of {hash, grid_point, replicate, document}");
  expand_command->callback([options] { expand(*options); });
}

}  // namespace aerobreak
