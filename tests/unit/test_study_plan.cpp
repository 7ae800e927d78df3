// `catena study`'s plan (settings, the default reference), its case records, targets and
// table (src/study/study_plan.cpp, case_record.cpp, study_table.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "catena/core/error.hpp"
#include "catena/study/case_record.hpp"
#include "catena/study/study_plan.hpp"
#include "catena/study/study_table.hpp"

namespace catena::study {
namespace {

using Strings = std::vector<std::string>;

TEST(Variation, ValuesSplitAtTopLevelCommasOnly) {
  const Variation v = parse_variation("integrator.dt=1e-3, 5e-4,2.5e-4");
  EXPECT_EQ(v.key, "integrator.dt");
  EXPECT_EQ(v.values, (Strings{"1e-3", "5e-4", "2.5e-4"}));
  const Variation g = parse_variation("gravity=[0, 0, -9.81],[0,0,-9.8]");
  EXPECT_EQ(g.values, (Strings{"[0, 0, -9.81]", "[0,0,-9.8]"}));
  const Variation m = parse_variation("a.b={mass: 1, stiffness: 2},'x,y'");
  EXPECT_EQ(m.values, (Strings{"{mass: 1, stiffness: 2}", "'x,y'"}));
}

TEST(Variation, MalformedArgumentsNameTheArgument) {
  for (const char* bad :
       {"integrator.dt", "=1,2", "integrator.dt=1,,2", "integrator.dt=1,1", "integrator.dt="}) {
    try {
      parse_variation(bad);
      ADD_FAILURE() << bad << ": no InputError";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().key, "--vary");
      EXPECT_NE(std::string(e.what()).find(std::string("'") + bad + "'"), std::string::npos)
          << e.what();
    }
  }
}

TEST(Settings, EveryCombinationTheFirstVariationSlowest) {
  const std::vector<Setting> s = expand(
      {parse_variation("integrator.type=hht,radau"), parse_variation("integrator.dt=0.01,0.005")});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].method(), "integrator.type=hht");
  EXPECT_EQ(s[0].resolution(), "integrator.dt=0.01");
  EXPECT_EQ(s[1].resolution(), "integrator.dt=0.005");
  EXPECT_EQ(s[2].method(), "integrator.type=radau");
  EXPECT_THROW(expand({parse_variation("a=1,2"), parse_variation("a=3")}), InputError);
  EXPECT_TRUE(expand({}).empty());
}

TEST(Settings, VaryingTheTypeRemovesTheKeysItDoesNotTake) {
  const std::vector<Setting> s = expand({parse_variation("integrator.type=hht,radau")});
  const Strings hht = s[0].overrides();
  const Strings radau = s[1].overrides();
  EXPECT_EQ(hht.front(), "integrator.type=hht");
  auto has = [](const Strings& v, const std::string& x) {
    return std::find(v.begin(), v.end(), x) != v.end();
  };
  EXPECT_TRUE(has(hht, "integrator.stages=~"));
  EXPECT_FALSE(has(hht, "integrator.alpha=~"));
  EXPECT_TRUE(has(radau, "integrator.alpha=~"));
  EXPECT_TRUE(has(radau, "integrator.local_newton=~"));
  EXPECT_FALSE(has(radau, "integrator.stages=~"));
  EXPECT_TRUE(keys_not_taken_by("no_such_method").empty());
}

TEST(Methods, EachPresetAtItsOwnStepsThenTheOtherVariations) {
  MethodContext context;
  context.scene_dt = 5e-4;
  context.modal_basis = "study/modal_basis.h5";
  const std::vector<Setting> s = expand_methods(
      {"radau", "modal"}, {"2", "1"}, {parse_variation("catenary.presag=0.01,0.02")}, context);
  ASSERT_EQ(s.size(), 8u);
  EXPECT_EQ(s[0].method(), "radau catenary.presag=0.01");  // a line per preset and pre-sag
  EXPECT_EQ(s[0].resolution(), "integrator.dt=0.004");     // 4 x 2 x 0.5 ms
  EXPECT_EQ(s[1].method(), "radau catenary.presag=0.02");
  EXPECT_EQ(s[2].resolution(), "integrator.dt=0.002");
  const Strings radau = s[0].overrides();
  EXPECT_EQ(radau[0], "integrator.type=radau_iia");
  EXPECT_NE(std::find(radau.begin(), radau.end(), "integrator.alpha=~"), radau.end());
  const Strings modal = s[4].overrides();
  EXPECT_EQ(s[4].method(), "modal catenary.presag=0.01");
  EXPECT_NE(std::find(modal.begin(), modal.end(), "analysis.modal_basis=study/modal_basis.h5"),
            modal.end());
  EXPECT_EQ(expand_methods({"all"}, {"1"}, {}, context).size(), method_presets().size());
}

TEST(Methods, ALinearSceneRunsTheNonlinearPresetsNonlinear) {
  MethodContext context;
  context.scene_dt = 1e-3;
  context.scene_nonlinear = false;
  const Strings hht = expand_methods({"hht"}, {"1"}, {}, context)[0].overrides();
  EXPECT_NE(std::find(hht.begin(), hht.end(), "analysis.structure=nonlinear"), hht.end());
  EXPECT_NE(std::find(hht.begin(), hht.end(), "analysis.modal_cutoff=~"), hht.end());
}

TEST(Methods, BadNamesStepsAndAVariedStepAreRefused) {
  MethodContext context;
  context.scene_dt = 1e-3;
  EXPECT_THROW(expand_methods({"euler"}, {"1"}, {}, context), InputError);
  EXPECT_THROW(expand_methods({"hht"}, {"0"}, {}, context), InputError);
  EXPECT_THROW(expand_methods({"hht"}, {"x"}, {}, context), InputError);
  EXPECT_THROW(expand_methods({"hht"}, {"1"}, {parse_variation("integrator.dt=1e-3")}, context),
               InputError);
}

TEST(CaseStem, FromTheSettingsContentReadableAndSafe) {
  EXPECT_EQ(case_stem("radau", "integrator.dt=0.004"), "radau_dt=0.004");
  EXPECT_EQ(case_stem("integrator.type=hht", "integrator.dt=0.04"), "type=hht_dt=0.04");
  EXPECT_EQ(case_stem("modal catenary.presag=0.01", ""), "modal_presag=0.01");
  EXPECT_EQ(case_stem("gravity=[0, 0, -9.8]", "lines[0].elements=40"),
            "gravity=_0__0__-9.8__lines_0_.elements=40");
  EXPECT_EQ(case_stem("", ""), "setting");
  EXPECT_EQ(case_stem(std::string(200, 'a'), "").size(), 96u);
  EXPECT_EQ(case_stem("a/b", "c\\d").find('/'), std::string::npos);
}

TEST(Reference, RefinesTheTightestResolutionAndChecksAgainstItUnrefined) {
  const ReferencePlan p = default_reference(
      {parse_variation("integrator.type=hht,radau"),
       parse_variation("integrator.dt=4e-3,1e-3,2e-3"), parse_variation("lines[0].elements=40,80")},
      0.02);
  EXPECT_EQ(p.overrides, (Strings{"integrator.dt=5e-04", "lines[0].elements=160"}));
  EXPECT_EQ(p.check_overrides, (Strings{"integrator.dt=1e-3", "lines[0].elements=80"}));
  EXPECT_NE(p.description.find("integrator.dt 1e-3 -> 5e-04"), std::string::npos) << p.description;
}

TEST(Reference, HalvesTheScenesStepWhenTheStepIsNotVaried) {
  const ReferencePlan p = default_reference({parse_variation("integrator.rtol=1e-3,1e-4")}, 0.002);
  EXPECT_EQ(p.overrides, (Strings{"integrator.rtol=1e-05", "integrator.dt=0.001"}));
  EXPECT_EQ(p.check_overrides, (Strings{"integrator.rtol=1e-4", "integrator.dt=0.002"}));
  EXPECT_THROW(default_reference({parse_variation("integrator.dt=0.01,fine")}, 0.01), InputError);
  EXPECT_THROW(default_reference({parse_variation("integrator.dt=0.01,-1")}, 0.01), InputError);
}

TEST(Reference, GivenOnTheCommandLineHasNoCheck) {
  const ReferencePlan p = given_reference({"integrator.type=radau", "integrator.dt=1e-4"});
  EXPECT_TRUE(p.check_overrides.empty());
  EXPECT_EQ(p.overrides[0], "integrator.type=radau");
  EXPECT_NE(std::find(p.overrides.begin(), p.overrides.end(), "integrator.alpha=~"),
            p.overrides.end());
}

TEST(CaseRecord, RoundTripsAndRefusesOtherText) {
  CaseRecord r;
  r.overrides = {"integrator.dt=0.01", "catenary.contact_wire.rayleigh={mass: 1, stiffness: 2}"};
  r.completed = false;
  r.exit_code = 3;
  r.message = "Newton diverged\nat node 7";
  r.wall_seconds = 12.25;
  r.scene = digest("integrator: {dt: 0.01}");
  const auto back = parse_record(record_text(r));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->overrides, r.overrides);
  EXPECT_FALSE(back->completed);
  EXPECT_EQ(back->exit_code, 3);
  EXPECT_EQ(back->message, "Newton diverged at node 7");
  EXPECT_EQ(back->wall_seconds, 12.25);
  EXPECT_EQ(back->scene, r.scene);
  EXPECT_EQ(digest(""), "cbf29ce484222325");  // FNV-1a's offset basis: the same everywhere
  EXPECT_NE(digest("integrator: {dt: 0.01}"), digest("integrator: {dt: 0.02}"));
  EXPECT_FALSE(parse_record("").has_value());
  EXPECT_FALSE(parse_record("catena-study-case 1\nstatus: maybe\n").has_value());
  EXPECT_FALSE(parse_record("catena-study-case 1\nexit_code: 0\n").has_value());  // no status

  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "catena_test_case.result";
  write_record(path, r);
  EXPECT_EQ(read_record(path)->overrides, r.overrides);
  std::filesystem::remove(path);
  EXPECT_FALSE(read_record(path).has_value());
}

TEST(Targets, MeasuresUnitsAndErrors) {
  const Target t = parse_target("sigma=1%");
  EXPECT_EQ(t.measure, "std");
  EXPECT_DOUBLE_EQ(t.limit, 1.0);
  EXPECT_DOUBLE_EQ(parse_target("force_rms_filtered=2.5N").limit, 2.5);
  EXPECT_DOUBLE_EQ(parse_target("probe_rms=1e-4m").limit, 1e-4);
  EXPECT_DOUBLE_EQ(parse_target("probe_rms=1e-4").limit, 1e-4);
  for (const char* bad : {"speed=1%", "std", "std=-1%", "std=1N", "std=abc"})
    EXPECT_THROW(parse_target(bad), InputError) << bad;
}

StudyRow row(const std::string& role, double wall, double std_error, bool completed = true) {
  StudyRow r;
  r.name = role + std::to_string(wall);
  r.role = role;
  r.completed = completed;
  r.work.wall_seconds = wall + 1.0;
  r.work.stepping_seconds = wall;
  r.work.t_reached = 2.0;
  r.errors.std = std_error;
  return r;
}

TEST(Recommendation, TheCheapestSettingWithinEveryTarget) {
  const std::vector<StudyRow> rows = {
      row("reference", 1.0, not_measured), row("setting", 10.0, 0.2),
      row("setting", 5.0, -0.8),           row("setting", 2.0, 3.0),
      row("setting", 1.0, 0.1, false),     row("setting+reference_check", 20.0, 0.05)};
  EXPECT_EQ(recommend(rows, {parse_target("std=1%")}), 2u);
  EXPECT_EQ(recommend(rows, {parse_target("std=0.1%")}), 5u);
  EXPECT_FALSE(recommend(rows, {parse_target("std=0.01%")}).has_value());
  EXPECT_FALSE(recommend(rows, {parse_target("probe_rms=1")}).has_value());  // not measured
}

TEST(Csv, HeaderRowsAndQuoting) {
  StudyRow r = row("setting", 4.0, 0.5);
  r.method = "integrator.type=radau";
  r.setting = "gravity=[0, 0, -9.8]";
  r.work.steps_accepted = 100;
  StudyRow failed = row("setting", 0.0, not_measured, false);
  failed.exit_code = 3;
  failed.message = "said \"no\"";
  const std::string csv = csv_text({r, failed});
  EXPECT_EQ(csv.rfind("case,role,method,setting,status,steps,rejected_steps,wall_seconds,"
                      "wall_per_simulated_second,newton_iterations,factorisations,",
                      0),
            0u);
  EXPECT_NE(csv.find(",std_error_percent,"), std::string::npos);
  EXPECT_NE(csv.find("\"gravity=[0, 0, -9.8]\",completed,100,0,4,2,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("failed (exit 3)"), std::string::npos);
  EXPECT_NE(csv.find("\"said \"\"no\"\"\""), std::string::npos);
}

}  // namespace
}  // namespace catena::study
