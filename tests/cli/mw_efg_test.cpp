// mw-efg end to end: the cantilever validation (errors, orders, CSV, ParaView files read back by
// VTK, the run in the provenance database), a short bending run with every output, and bad input - one line naming the value, exit 1,
// nothing written.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "mesowave/io/csv.hpp"
#include "support/run_tool.hpp"

using namespace mesowave::test;
namespace fs = std::filesystem;
using json = nlohmann::json;

TEST(MwEfg, CantileverConvergesAndWritesItsOutputs) {
  TempDir dir;
  const auto r = run_tool("mw-efg", {"cantilever", "--spacing-m", "4", "--refinements", "2", "--method", "both",
                                     "--table", (dir / "c.csv").string(), "--snapshots", (dir / "vtk").string(),
                                     "--out", (dir / "c.json").string(), "--db", (dir / "prov.sqlite").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(read_file(dir / "c.json"));
  ASSERT_EQ(j["runs"].size(), 6u);
  EXPECT_EQ(j["runs"][0]["method"], "EFG");
  EXPECT_EQ(j["runs"][0]["nodes"], 13 * 4);  // 12 x 3 cells
  EXPECT_EQ(j["runs"][2]["gauss_points"], 48 * 12 * 4);
  EXPECT_EQ(j["runs"][3]["method"], "Q4 FEM");
  // The Q4 FEM's L2 order is 2; the EFG's error is below the FEM's at every spacing.
  for (const auto& order : j["orders"]["Q4 FEM"]["displacement_L2"]) EXPECT_NEAR(order.get<double>(), 2.0, 0.25);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(j["runs"][k]["displacement_error_L2"].get<double>(), j["runs"][k + 3]["displacement_error_L2"].get<double>());
  const std::string csv = read_file(dir / "c.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);
  // ParaView's files, read back by VTK's own reader.
  const auto v = run_command(fs::path(MESOWAVE_SOURCE_DIR) / "scripts/check-vtk", {(dir / "vtk/cantilever.pvd").string()});
  if (v.exit_status == 2) ADD_FAILURE() << "VTK's Python module is missing: run scripts/install-deps";
  ASSERT_EQ(v.exit_status, 0) << v.out << v.err;
  const json vtk = json::parse(v.out);
  EXPECT_EQ(vtk[0]["datasets"][0]["points"], 49 * 13);  // the finest run's nodes
  EXPECT_EQ(vtk[0]["datasets"][0]["point_data"]["stress"]["components"], 6);
  // The run is recorded with its metrics.
  const auto show = run_tool("mw-prov", {"show", "1", "--json", "--db", (dir / "prov.sqlite").string()});
  ASSERT_EQ(show.exit_status, 0) << show.err;
  const json p = json::parse(show.out);
  EXPECT_EQ(p["tool"], "mw-efg");
  bool found = false;
  for (const auto& m : p["metrics"]) found = found || m["name"] == "efg_52_nodes_displacement_error";
  EXPECT_TRUE(found) << show.out;
}

TEST(MwEfg, BendingWritesCurvePlotCrackAndSummary) {
  TempDir dir;
  const fs::path lab = fs::path(MESOWAVE_SOURCE_DIR) / "lab-data/shock-concrete/three-point-bending.toml";
  const auto r = run_tool("mw-efg", {"bending", "--from", lab.string(), "--law", "bilinear", "--spacing-mm", "10",
                                     "--max-deflection-mm", "0.2", "--steps", "10", "--fem-refinement", "1", "--curve",
                                     (dir / "ld.csv").string(), "--plot", (dir / "ld.png").string(), "--crack-path",
                                     (dir / "crack.csv").string(), "--snapshots", (dir / "vtk").string(), "--out",
                                     (dir / "b.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(read_file(dir / "b.json"));
  EXPECT_EQ(j["law"], "bilinear");
  EXPECT_EQ(j["material"]["G_f_N_m"], 113.0);  // from the lab-data file
  EXPECT_NEAR(j["G_f_times_ligament_Nmm"].get<double>(), 565.0, 1e-9);
  EXPECT_GT(j["peak_load_N"].get<double>(), 0);
  const std::size_t points = j["cost"]["curve_points"];
  EXPECT_GE(points, 11u);  // (0, 0), 10 steps, the state before each crack extension
  // The stiffness beside its references: the FEM of the same beam, beam theory above both.
  const auto& k = j["elastic_stiffness"];
  EXPECT_LT(k["fem_notched_N_per_mm"].get<double>(), k["beam_theory_plus_lefm_notch_N_per_mm"].get<double>());
  EXPECT_NEAR(k["efg_over_fem"].get<double>(), 1.0, 0.3);
  const std::string curve = read_file(dir / "ld.csv");
  EXPECT_EQ(std::size_t(std::count(curve.begin(), curve.end(), '\n')), points + 1);
  EXPECT_EQ(curve.rfind("deflection_mm,load_N", 0), 0u);
  EXPECT_GT(fs::file_size(dir / "ld.png"), 1000u);
  EXPECT_EQ(read_file(dir / "crack.csv").rfind("x_mm,y_mm\n225,0\n225,50", 0), 0u);
  const auto v = run_command(fs::path(MESOWAVE_SOURCE_DIR) / "scripts/check-vtk", {(dir / "vtk/bending.pvd").string()});
  ASSERT_EQ(v.exit_status, 0) << v.out << v.err;
  const auto datasets = json::parse(v.out)[0]["datasets"];
  EXPECT_EQ(datasets.size(), 2 * points);
  // the last point's nodes: every node with its displacement and stress, the beam bent downward
  const auto& nodes = datasets[datasets.size() - 2];
  EXPECT_EQ(nodes["point_data"]["displacement"]["tuples"], nodes["points"]);
  EXPECT_EQ(nodes["point_data"]["stress"]["components"], 6);
  EXPECT_GT(nodes["point_data"]["displacement"]["range"][1].get<double>(), 0.0);
  // the last point's crack: the notch (one traction-free segment, damage 1) and the grown cohesive crack, a piece
  // per cohesive Gauss point, with its opening [mm], traction [MPa] (at most f_t = 2.4 MPa) and damage in [0, 1]
  const auto& crack = datasets.back();
  const std::size_t cells = j["cost"]["cohesive_points"].get<std::size_t>() + 1;
  EXPECT_GT(cells, 1u);
  EXPECT_EQ(crack["lines"], cells);
  for (const char* a : {"opening_mm", "traction_MPa", "damage"}) EXPECT_EQ(crack["cell_data"][a]["tuples"], cells) << a;
  const auto& w = crack["cell_data"]["opening_mm"]["range"];
  EXPECT_GT(w[1].get<double>(), 1e-3);  // opened past a micrometre at 0.2 mm deflection, beyond the peak
  EXPECT_LT(w[1].get<double>(), j["w_max_mm"].get<double>() * 2);
  EXPECT_LE(crack["cell_data"]["traction_MPa"]["range"][1].get<double>(), 2.4 * (1 + 1e-9));
  EXPECT_EQ(crack["cell_data"]["damage"]["range"][1].get<double>(), 1.0);
  EXPECT_GE(crack["cell_data"]["damage"]["range"][0].get<double>(), 0.0);
  EXPECT_EQ(crack["bounds"][0].get<double>(), 0.225);  // vertical at mid-span, from the mouth
  EXPECT_EQ(crack["bounds"][2].get<double>(), 0.0);
}

// --from the lab-data file gives the law what the file holds (f_c: the bilinear law's beta_t by Eq. (22)) and the same
// run spelled out option by option gives the same bits; a different f_c reaches the law and moves the curve; the law's
// own constants come from the registry (alpha_t = 0.14) unless an option names them.
TEST(MwEfg, LabDataReachesTheLawAsTheExplicitOptionsDo) {
  TempDir dir;
  const fs::path lab = fs::path(MESOWAVE_SOURCE_DIR) / "lab-data/shock-concrete/three-point-bending.toml";
  const std::vector<std::string> run = {"bending", "--spacing-mm", "10", "--max-deflection-mm", "0.2", "--steps", "8",
                                        "--fem-refinement", "0"};
  auto bending = [&](const std::string& name, std::vector<std::string> extra, const std::string& law = "bilinear") {
    auto args = run;
    args.insert(args.end(), {"--law", law});
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"--curve", (dir / (name + ".csv")).string(), "--out", (dir / (name + ".json")).string()});
    const auto r = run_tool("mw-efg", args);
    EXPECT_EQ(r.exit_status, 0) << name << ": " << r.err;
    return json::parse(read_file(dir / (name + ".json")));
  };
  const json from = bending("from", {"--from", lab.string()});
  const json spelled = bending("spelled", {"--E-GPa", "20", "--nu", "0.2", "--f-t-MPa", "2.4", "--G-f-N-m", "113",
                                           "--span-mm", "450", "--depth-mm", "100", "--notch-mm", "50", "--thickness-mm",
                                           "100", "--f-c-MPa", "22.6", "--alpha-t", "0.14"});
  const json strong = bending("strong", {"--from", lab.string(), "--f-c-MPa", "50"});
  EXPECT_EQ(read_file(dir / "from.csv"), read_file(dir / "spelled.csv"));
  for (const char* key : {"material", "geometry_mm", "law_parameters", "peak_load_N", "work_of_fracture_Nmm", "dissipated_Nmm"})
    EXPECT_EQ(from[key], spelled[key]) << key;
  EXPECT_NEAR(from["material"]["f_c_MPa"].get<double>(), 22.6, 1e-12);
  EXPECT_EQ(from["law_parameters"]["alpha_t"], 0.14);
  EXPECT_EQ(from["law_parameters"]["beta_t"], 0.25);  // Eq. (22) below 30 MPa
  EXPECT_EQ(from["law_keys"].size(), 0u);             // alpha_t from the registry's one default
  EXPECT_NEAR(strong["law_parameters"]["beta_t"].get<double>(), 0.22, 1e-12);  // 0.25 - 0.0015 (50 - 30)
  EXPECT_NE(read_file(dir / "from.csv"), read_file(dir / "strong.csv"));
  // the exponential law takes the same file: f_c is no concern of it, alpha is the registry's
  const json exponential = bending("exponential", {"--from", lab.string()}, "exponential");
  EXPECT_EQ(exponential["law_parameters"]["alpha"], 2.0);
  EXPECT_NEAR(exponential["w_max_mm"].get<double>(), 3 * 113.0 / 2.4e6 * 1e3, 1e-12);  // Eq. (20)
}

TEST(MwEfg, WaveWritesHistoriesSummaryAndSnapshots) {
  TempDir dir;
  const auto r = run_tool("mw-efg", {"wave", "--length-mm", "200", "--spacing-mm", "10", "--sensor-mm", "50", "--sensor-mm",
                                     "150", "--history", (dir / "h.csv").string(), "--snapshots", (dir / "vtk").string(),
                                     "--snapshot-stride", "20", "--threads", "1", "--out", (dir / "w.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json j = json::parse(read_file(dir / "w.json"));
  EXPECT_LT(j["energy_drift"].get<double>(), 1e-12);
  EXPECT_LE(j["dt_us"].get<double>(), j["stable_dt_us"].get<double>());
  EXPECT_NEAR(j["c_p_m_s"].get<double>(), std::sqrt(30e9 * 0.8 / (1.2 * 0.6) / 2400), 1e-6);
  const std::int64_t steps = j["steps"];
  const std::string h = read_file(dir / "h.csv");
  EXPECT_EQ(h.rfind("t_us,x0_sigma_xx_MPa,x0_sigma_yy_MPa,x0_v_x_m_s,x0_v_y_m_s,x1_sigma_xx_MPa", 0), 0u);
  EXPECT_EQ(std::int64_t(std::count(h.begin(), h.end(), '\n')), steps + 1);  // header + every step
  const auto v = run_command(fs::path(MESOWAVE_SOURCE_DIR) / "scripts/check-vtk", {(dir / "vtk/wave.pvd").string()});
  ASSERT_EQ(v.exit_status, 0) << v.out << v.err;
  EXPECT_EQ(json::parse(v.out)[0]["datasets"].size(), 2 * std::size_t((steps - 1) / 20 + 2));  // every 20th and the last
}

// The stiffening laws by name: the characteristics' block in the summary (its x_b against the
// quadratic law's closed form at the front, c_0 M t_r / (beta p_max)), the profiles along the
// centre line; the linear run's history carries the closed form -p(t - x / c_p) beside each sensor.
TEST(MwEfg, WaveLawsCharacteristicsProfilesAndTheContinuum) {
  TempDir dir;
  const auto r = run_tool("mw-efg", {"wave", "--law", "quadratic", "--beta", "40", "--length-mm", "100", "--width-mm", "8",
                                     "--spacing-mm", "2", "--E-GPa", "20", "--peak-MPa", "500", "--rise-us", "20",
                                     "--fall-us", "20", "--duration-us", "30", "--stiffness-check", "1", "--sensor-mm", "10", "--sensor-mm", "30",
                                     "--profiles", (dir / "p.csv").string(), "--profile-us", "10", "--profile-us", "25",
                                     "--threads", "1", "--out", (dir / "q.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json q = json::parse(read_file(dir / "q.json"));
  EXPECT_EQ(q["law"], "quadratic");
  const double M = 20e9 * 0.8 / (1.2 * 0.6), c0 = std::sqrt(M / 2400);
  EXPECT_NEAR(q["characteristics"]["formation_distance_mm"].get<double>(), c0 * M * 20e-6 / (40 * 500e6) * 1e3, 1e-6);
  EXPECT_EQ(q["characteristics"]["fronts"].size(), 2u);
  EXPECT_EQ(q["profiles"].size(), 2u);
  EXPECT_NEAR(q["profiles"][1]["snapshot_us"].get<double>(), 25, q["dt_us"].get<double>());  // every other step kept
  const std::string p = read_file(dir / "p.csv");
  EXPECT_EQ(p.rfind("x_mm,p_MPa_at_10us,p_MPa_at_25us\n0,", 0), 0u) << p.substr(0, 80);
  EXPECT_EQ(std::count(p.begin(), p.end(), '\n'), 1 + 51);  // the centre row's 51 nodes

  const auto l = run_tool("mw-efg", {"wave", "--length-mm", "200", "--spacing-mm", "10", "--sensor-mm", "50", "--rise-us",
                                     "10", "--fall-us", "10", "--history", (dir / "h.csv").string(), "--threads", "1"});
  ASSERT_EQ(l.exit_status, 0) << l.err;
  const auto h = mesowave::io::read_csv(dir / "h.csv");
  const auto t = h.column("t_us"), exact = h.column("x0_sigma_xx_continuum_MPa");
  const double c_p = std::sqrt(30e9 * 0.8 / (1.2 * 0.6) / 2400);
  for (std::size_t i = 0; i < h.rows.size(); i += 7) {
    const double tau = h.number(i, t) * 1e-6 - 0.05 / c_p;  // the triangle 100 MPa, 10 us up, 10 us down
    const double pulse = tau <= 0 ? 0 : tau < 10e-6 ? 100 * tau / 10e-6 : tau < 20e-6 ? 100 * (20e-6 - tau) / 10e-6 : 0;
    EXPECT_NEAR(h.number(i, exact), -pulse, 1e-6) << h.number(i, t);  // before the reflection returns (0.35 m / c_p)
  }
}

// --fem-reference: mw-fem's bar beside the EFG strip under the same 20 kHz burst (the set-up of
// tests/efg/wave_strip_test.cpp's HannBurstAgreesWithTheFemOnTheSameBar, made here by the tool):
// the lumped-mass Q1 bar lags by 1 - sin(kh/2)/(kh/2) = 1.2e-3 at k h = 0.17, the EFG by its
// stencil's 0.5-0.8 %, so the FEM is the closer to the closed form and the difference between
// them is the EFG's error.
TEST(MwEfg, WaveFemReferenceOnTheSameBar) {
  TempDir dir;
  const auto r = run_tool("mw-efg", {"wave", "--pulse", "hann", "--frequency-kHz", "20", "--cycles", "3", "--peak-MPa", "1",
                                     "--length-mm", "800", "--spacing-mm", "5", "--sensor-mm", "300", "--duration-us", "250",
                                     "--fem-reference", "--history", (dir / "h.csv").string(), "--threads", "1", "--out",
                                     (dir / "w.json").string()});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json f = json::parse(read_file(dir / "w.json"))["fem_reference"]["sensors"]["x0"];
  const double e_efg = f["efg_rms_error"], e_fem = f["fem_rms_error"], between = f["efg_fem_rms_difference"];
  EXPECT_LT(e_fem, 0.5 * e_efg);
  EXPECT_NEAR(between / e_efg, 1.0, 0.3);
  const std::string h = read_file(dir / "h.csv");
  EXPECT_NE(h.substr(0, h.find('\n')).find("x0_v_x_fem_m_s,x0_v_x_continuum_m_s"), std::string::npos);
}

TEST(MwEfg, BadInputIsOneLineNamingTheValueAndWritesNothing) {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"cantilever", "--nu", "0.5"}, "nu"},
      {{"cantilever", "--nu", "0.7", "--method", "fem"}, "0.7"},
      {{"cantilever", "--support-scale", "0.6"}, "Gauss point"},  // a support with too few nodes
      {{"cantilever", "--spacing-m", "-1"}, "--spacing-m (-1 m)"},
      {{"cantilever", "--basis", "cubic"}, "cubic"},
      {{"bending", "--notch-mm", "120"}, "notch"},  // a notch deeper than the beam
      {{"bending", "--nu", "0.5"}, "nu (0.5)"},
      {{"bending", "--G-f-N-m", "0"}, "G_f"},
      {{"bending", "--f-t-MPa", "-1"}, "f_t"},
      {{"bending", "--support-scale", "0.5", "--fem-refinement", "0"}, "nodes reach"},  // a support with too few nodes
      {{"bending", "--law", "linear"}, "linear"},
      {{"bending", "--law", "bilinear", "--alpha", "3"}, "unknown key alpha"},  // a key of the other law
      {{"bending", "--alpha", "0"}, "alpha (0)"},
      {{"bending", "--law", "bilinear", "--f-c-MPa", "-30"}, "f_c (-30 MPa)"},
      {{"bending", "--notch-x-mm", "460"}, "notch: point 0 (0.46, 0) m lies outside the body"},  // a crack outside the body
      {{"bending", "--notch-x-mm", "0"}, "lies on the boundary"},
      {{"bending", "--notch-x-mm", "150", "--spacing-mm", "10"}, "node column at x = 0.15 m"},
      {{"wave", "--dt-us", "5"}, "exceeds the stable step"},
      {{"wave", "--rise-us", "0", "--fall-us", "0"}, "pulse length"},
      {{"wave", "--pulse", "friedlander", "--positive-us", "0"}, "positive-phase"},
      {{"wave", "--dt-fraction", "0"}, "fraction"},
      {{"wave", "--width-mm", "4"}, "at least 2 node spacings"},
      {{"wave", "--sensor-mm", "900"}, "sensor x"},
      {{"wave", "--density-kg-m3", "0"}, "density"},
      {{"wave", "--law", "cubic"}, "--law cubic"},
      {{"wave", "--law", "quadratic", "--beta", "0"}, "--beta (0)"},
      {{"wave", "--unloading", "2"}, "--unloading (2)"},
      {{"wave", "--profiles", "p.csv"}, "--profile-us"},
      {{"wave", "--fem-reference"}, "--pulse hann"},
      {{"wave", "--pulse", "hann", "--fem-reference", "--sensor-mm", "102"}, "must lie on a node of the FEM bar"},
      {{"wave", "--pulse", "hann", "--frequency-kHz", "0"}, "--frequency-kHz"},
      {{"wave", "--viscosity-quadratic", "-1"}, "C_0 (quadratic, -1)"},
      {{"wave", "--viscosity-linear", "-0.5"}, "C_1 (linear, -0.5)"},
      {{"blast", "--min-crack-spacing-mm", "-30"}, "minimum crack spacing (-0.03 m)"},
      {{"blast", "--min-crack-radius-mm", "-15"}, "minimum crack radius (-0.015 m)"},
      {{"blast", "--crushing-eps-v", "-0.05"}, "crushing volumetric strain (-0.05)"},
  };
  for (const auto& c : cases) {
    TempDir dir;
    auto args = c.args;
    args.insert(args.end(), {"--out", (dir / "o.json").string()});
    if (c.args[0] == "cantilever") args.insert(args.end(), {"--table", (dir / "t.csv").string()});
    else if (c.args[0] == "wave") args.insert(args.end(), {"--history", (dir / "h.csv").string(), "--snapshots", (dir / "vtk").string()});
    else if (c.args[0] == "blast") args.insert(args.end(), {"--cracks", (dir / "c.csv").string(), "--snapshots", (dir / "vtk").string()});
    else args.insert(args.end(), {"--curve", (dir / "c.csv").string(), "--snapshots", (dir / "vtk").string()});
    const auto r = run_tool("mw-efg", args);
    EXPECT_EQ(r.exit_status, 1) << c.args[1] << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(count_files(dir.path()), 0u) << c.args[1];
  }
}

// The shock viscosity's options reach the explicit run of both subcommands: off by default (no viscous
// work), on with LS-DYNA's coefficients (work done, the identity still closed, the CSV's column).
TEST(MwEfg, ViscosityOptionsReachWaveAndBlast) {
  TempDir dir;
  const std::vector<std::string> wave = {"wave", "--law", "quadratic", "--beta", "40", "--length-mm", "100", "--width-mm", "8",
                                         "--spacing-mm", "2", "--E-GPa", "20", "--peak-MPa", "500", "--rise-us", "20",
                                         "--fall-us", "20", "--duration-us", "30", "--stiffness-check", "1", "--threads", "1"};
  auto off_args = wave, on_args = wave;
  off_args.insert(off_args.end(), {"--out", (dir / "off.json").string()});
  on_args.insert(on_args.end(), {"--viscosity-quadratic", "1.5", "--viscosity-linear", "0.06", "--out", (dir / "on.json").string()});
  ASSERT_EQ(run_tool("mw-efg", off_args).exit_status, 0);
  const auto r = run_tool("mw-efg", on_args);
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const json off = json::parse(read_file(dir / "off.json")), on = json::parse(read_file(dir / "on.json"));
  EXPECT_FALSE(off["viscosity"]["on"].get<bool>());
  EXPECT_EQ(off["viscosity"]["viscous_work_J"].get<double>(), 0.0);
  EXPECT_TRUE(on["viscosity"]["on"].get<bool>());
  EXPECT_EQ(on["viscosity"]["C_0_quadratic"].get<double>(), 1.5);
  EXPECT_GT(on["viscosity"]["viscous_work_J"].get<double>(), 0.0);
  EXPECT_LT(on["energy_drift"].get<double>(), 1e-12);
  const auto b = run_tool("mw-efg", {"blast", "--span-mm", "200", "--thickness-mm", "60", "--spacing-mm", "10", "--peak-MPa", "1000",
                                     "--duration-us", "20", "--threads", "1", "--viscosity-quadratic", "1.5", "--viscosity-linear",
                                     "0.06", "--energy", (dir / "e.csv").string(), "--out", (dir / "b.json").string()});
  ASSERT_EQ(b.exit_status, 0) << b.err;
  const json j = json::parse(read_file(dir / "b.json"));
  EXPECT_GT(j["energy"]["viscous_J"].get<double>(), 0.0);
  EXPECT_NEAR(j["crater"]["crushing_eps_v"].get<double>(), 0.0475, 5e-5);  // the crater block, its default eps_crush
  EXPECT_LT(j["energy"]["run_drift"].get<double>(), 1e-12);
  const std::string e = read_file(dir / "e.csv");
  EXPECT_NE(e.substr(0, e.find('\n')).find(",viscous_J"), std::string::npos);
}

TEST(MwEfg, HelpTeachesTheSubcommands) {
  const auto r = run_tool("mw-efg", {"--help"});
  EXPECT_EQ(r.exit_status, 0);
  for (const char* word : {"cantilever", "bending", "Timoshenko", "Koermeling", "--from"}) EXPECT_NE(r.out.find(word), std::string::npos) << word;
}
