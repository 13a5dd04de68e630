// Whole impact runs with known answers: a slow cluster sticks to an adhesive wall, a small stiff
// cluster bounces off a wall without adhesion, a fast one breaks up, a too short time limit is
// undetermined, and the reduced figure-4 case (report section 3.3) does not break up. Each result
// document is checked against schemas/result.schema.json.
#include <catch2/catch.hpp>

#include <cmath>

#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/impact/impact_run.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;
using Catch::Matchers::WithinAbs;

namespace {

ImpactResult run(const Json& document) { return run_impact(parse_impact_case(document)); }

// Every result must be a valid result document whose energy ledger closes.
void check_document(const ImpactResult& r) {
  const Json document = to_json(r);
  const auto violations = validate_result(document);
  INFO(describe(violations));
  CHECK(violations.empty());
  CHECK(document["outcome"]["class"] == to_string(r.classification.outcome));
  CHECK(document["fragments"]["list"].size() == r.fragments.size());
  CHECK(std::abs(document["energy"]["balance_drift"].get<double>()) < 0.05);
  // Contacts are counted consistently: final = initial + made - broken.
  CHECK(r.final_contacts + r.pair_events.broken == r.initial_contacts + r.pair_events.made);
  CHECK(r.final_wall_contacts + r.wall_events.broken == r.wall_events.made);
}

std::size_t primaries(const ImpactResult& r) {
  std::size_t n = 0;
  for (const Fragment& f : r.fragments) n += f.size;
  return n;
}

}  // namespace

TEST_CASE("a slow cluster sticks to an adhesive wall") {
  Json c = testing::minimal_case();
  c["material"]["gamma_over_kn"] = 0.01;
  c["model"] = {{"damping", {{"law", "viscoelastic"}, {"dissipative_time", 0.05}}},
                {"rolling", {{"enabled", true}, {"critical_displacement", 0.02}}},
                {"twisting", true}};
  c["impact"]["speed"] = 0.005;
  c["wall"] = {{"adhesive", true}};
  c["run"]["time_limit"] = 20000;
  const ImpactResult r = run(c);
  INFO(to_json(r)["outcome"].dump() << " " << r.unsettled_reason);
  CHECK(r.settled);
  CHECK(r.classification.outcome == ImpactOutcome::stick);
  CHECK(r.fragments.size() == 1);
  CHECK(r.fragments.front().on_wall());
  CHECK_THAT(r.mass_fraction_on_wall, WithinAbs(1.0, 1e-12));
  CHECK(std::abs(r.restitution_normal) < 0.01);
  CHECK(r.final_wall_contacts > 0);
  CHECK(r.settled_at <= 20000.0);
  check_document(r);
}

TEST_CASE("a small stiff cluster bounces off a wall without adhesion") {
  Json c = testing::minimal_case();
  c["material"]["gamma_over_kn"] = 0.01;
  c["model"] = {{"rolling", {{"enabled", true}, {"critical_displacement", 0.05}}}, {"twisting", true}};
  c["impact"]["speed"] = 0.005;
  c["wall"] = {{"adhesive", false}};
  c["run"]["time_limit"] = 20000;
  const ImpactResult r = run(c);
  INFO(to_json(r)["outcome"].dump() << " " << r.unsettled_reason);
  CHECK(r.settled);
  CHECK(r.classification.outcome == ImpactOutcome::bounce);
  CHECK(r.fragments.size() == 1);
  CHECK_FALSE(r.fragments.front().on_wall());
  CHECK(r.fragments.front().normal_velocity > 0.0);
  CHECK(r.restitution_normal > 0.1);
  CHECK(r.restitution_normal <= 1.0 + 1e-6);
  CHECK(r.mass_fraction_on_wall == 0.0);
  check_document(r);
}

TEST_CASE("a fast cluster breaks up") {
  Json c = testing::minimal_case();
  c["cluster"]["generator"]["primaries"] = 32;
  c["material"]["gamma_over_kn"] = 0.001;
  c["impact"]["speed"] = 0.02;  // lambda (eq 19) = 0.14: the bonds hold a small share of the kinetic energy
  c["wall"] = {{"adhesive", false}};
  c["run"]["time_limit"] = 5000;
  const ImpactResult r = run(c);
  INFO(to_json(r)["outcome"].dump() << " " << r.unsettled_reason);
  CHECK(r.settled);
  CHECK(r.classification.outcome == ImpactOutcome::break_up);
  CHECK(r.fragments.size() > 3);
  CHECK(r.classification.largest_fragment_share < 0.9);
  CHECK(primaries(r) == 32);
  CHECK(r.pair_events.broken > 0);
  for (const Fragment& f : r.fragments) CHECK((f.on_wall() || f.normal_velocity > 0.0));
  check_document(r);
}

TEST_CASE("an impact that has not settled by the time limit is undetermined") {
  Json c = testing::minimal_case();
  c["run"]["time_limit"] = 20.0;
  const ImpactResult r = run(c);
  CHECK_FALSE(r.settled);
  CHECK(r.classification.outcome == ImpactOutcome::undetermined);
  CHECK(r.simulated_time >= 20.0);
  CHECK(r.simulated_time < 20.0 + 2.0 * r.time_step);
  const Json document = to_json(r);
  CHECK(document["outcome"]["class"] == "undetermined");
  CHECK(document["run"]["settled_at"].is_null());
  CHECK(document["run"]["unsettled_reason"].is_string());
  check_document(r);
}

TEST_CASE("the reduced figure-4 case (256 primaries) is ductile: no break-up") {
  const ImpactCase c = load_impact_case(testing::source_path("studies/figure4_impact_n256.case.json"));
  const ImpactResult r = run_impact(c);
  INFO(to_json(r)["outcome"].dump() << " " << r.unsettled_reason);
  CHECK(r.settled);
  CHECK(r.classification.outcome != ImpactOutcome::break_up);
  CHECK(r.classification.outcome != ImpactOutcome::undetermined);
  CHECK(r.classification.largest_fragment_share >= 0.9);
  // Ductile: the cluster flattens against the wall, its contacts rearrange.
  CHECK(r.pair_events.made > 0);
  CHECK(r.after.radius_of_gyration != r.before.radius_of_gyration);
  check_document(r);
}
