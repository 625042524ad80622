// Virtual lab tests (dem/calibration/uniaxial_analysis.hpp) against closed forms: the
// compression of a simple cubic lattice, the tension of a chain, and the
// analysis itself on a curve whose modulus, Poisson ratio and peak are known.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/scene/scene.hpp"
#include "mesowave/dem/engine/simulation.hpp"
#include "mesowave/dem/calibration/uniaxial_analysis.hpp"
#include "dem/test_packings.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

// The lattice compression of dem/test_packings.hpp (walls on z, extensometers on the face x-) with
// the modulus levels as fractions of the peak; with C_f = 1.05 each sphere of the simple cubic
// lattice is bonded to its six neighbours only (the face diagonals are 2.83 r apart).
const std::string kCompression = dem::testing::lattice_compression_toml("modulus_levels_pct = [20.0, 80.0]");

}  // namespace

TEST(VirtualCompression, SimpleCubicLatticeHasHalfTheContactModulus) {
  // Each column of the lattice is a chain of bonds K_n = E_dem r (Eq. 3 with
  // equal radii) spaced 2r and carrying the stress over (2r)^2:
  // E_glob = K_n / (2r) = E_dem / 2; no bond is inclined, so nu_glob = 0.
  const double r = 1e-3;
  const Scene scene = parse_scene(kCompression, "compression");
  Simulation sim(scene, dem::testing::simple_cubic_packing(6, r, 2500.0));
  EXPECT_EQ(sim.choice().model, "full");
  const RunReport report = sim.run();
  ASSERT_TRUE(report.test);
  const UniaxialTestResult& t = *report.test;
  EXPECT_NEAR(t.area_m2, std::pow(12 * r, 2), 1e-12);
  // What is left is the dynamics of a test loaded in 0.8 ms (~1e-6).
  EXPECT_NEAR(t.E_secant_Pa / 10e9, 1.0, 1e-5);
  EXPECT_NEAR(t.E_fit_Pa / 10e9, 1.0, 1e-5);
  ASSERT_TRUE(t.nu_secant);
  EXPECT_NEAR(*t.nu_secant, 0.0, 1e-9);
  EXPECT_FALSE(t.peak_reached);  // unbreakable bonds: still rising at the end
}

TEST(VirtualCompression, WallsAddTheirStiffnessToTheCriticalStep) {
  // A wall spring E_dem r on a sphere of mass m adds E_dem r / m to lambda_max
  // (Weyl): the limit falls below the bonded network's own.
  const double r = 1e-3, rho = 2500;
  const Scene scene = parse_scene(kCompression, "compression");
  const Simulation sim(scene, dem::testing::simple_cubic_packing(6, r, rho));
  const double m = rho * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(sim.time_step().boundary_lambda, 20e9 * r / m, 1e-9 * 20e9 * r / m);
  const double without = 2.0 / std::sqrt(sim.time_step().lambda_max - sim.time_step().boundary_lambda);
  EXPECT_LT(sim.time_step().eigenvalue_s, without);
}

TEST(VirtualTension, ChainModulusIsKnTimesSpacingOverPiR2) {
  // Rod paper, Section 3: E_DEM = K_n d / (pi R^2), K_n = E_dem R.
  const double R = 5e-3, d = 1.05 * R, E_dem = 640e9, rho = 6000;
  const std::string text = R"(
[packing]
file = "unused.h5"
[material]
E_dem_GPa = 640.0
damping = 0.3
bond_factor = 0.75
[time]
dt_ns = 500
duration_ms = 5
[[actuator]]
name = "hold"
kind = "velocity"
sphere = "first"
direction = "-line"
velocity_mm_s = 0.0
[[actuator]]
name = "pull"
kind = "velocity"
sphere = "last"
direction = "line"
velocity_mm_s = 5.0
ramp_us = 500
[[sensor]]
name = "F"
quantity = "force"
actuator = "pull"
sample_interval_ns = 5000
[[sensor]]
name = "strain"
quantity = "strain"
component = "line"
between = ["first", "last"]
sample_interval_ns = 5000
[test]
kind = "tension"
load = ["F"]
axial = ["strain"]
modulus_levels_pct = [20.0, 90.0]
inertial_number_bound = 0.0
)";
  Simulation sim(parse_scene(text, "tension"), dem::testing::line_packing(41, R, d, rho));
  EXPECT_EQ(sim.choice().model, "chain");
  const RunReport report = sim.run();
  ASSERT_TRUE(report.test);
  const double expected = E_dem * R * d / (std::numbers::pi * R * R);
  EXPECT_NEAR(report.test->area_m2, std::numbers::pi * R * R, 1e-15);
  // The fit averages the waves the start of the pull leaves in the force
  // (3e-7 measured); the secant reads two samples of them (8e-5).
  EXPECT_NEAR(report.test->E_fit_Pa / expected, 1.0, 1e-6);
  EXPECT_NEAR(report.test->E_secant_Pa / expected, 1.0, 2e-4);
}

namespace {

// Signals of a test whose curve is known: stress rises linearly with a
// modulus E to a peak at sample `peak`, then falls; the lateral strain is
// -nu times the axial one; a compression test's extensometers shorten.
std::vector<signal::Signal> known_curve(double E, double nu, std::size_t peak, std::size_t n, double area) {
  signal::Signal load{.name = "P", .quantity = "force", .unit = "N", .component = "", .t0_s = 0, .dt_s = 1e-4,
                      .samples = {}, .position_m = std::nullopt};
  signal::Signal axial = load, lateral = load;
  axial.name = "V";
  lateral.name = "H";
  for (std::size_t i = 0; i < n; ++i) {
    const double eps = 1e-5 * double(i);
    const double sigma = i <= peak ? E * eps : E * 1e-5 * double(peak) * (1.0 - 0.02 * double(i - peak));
    load.samples.push_back(sigma * area);
    axial.samples.push_back(-eps);
    lateral.samples.push_back(nu * eps);
  }
  return {load, axial, lateral};
}

UniaxialTestSpec compression_spec() {
  UniaxialTestSpec s;
  s.kind = UniaxialTestSpec::Kind::compression;
  s.load = {"P"};
  s.axial = {"V"};
  s.lateral = {"H"};
  s.inertial_number_bound = 1e-4;
  return s;
}

}  // namespace

TEST(UniaxialTestAnalysis, ReadsTheModulusPoissonRatioAndPeakOfAKnownCurve) {
  const double E = 27e9, nu = 0.16, area = 2.5e-3;
  const auto signals = known_curve(E, nu, 200, 260, area);
  const UniaxialTestSpecimen specimen{area, 1.8e-3, 2290};
  const UniaxialTestResult r = analyse_uniaxial_test(signals, compression_spec(), specimen);
  EXPECT_NEAR(r.peak_stress_Pa, E * 200e-5, 1e-6 * E * 200e-5);
  EXPECT_EQ(r.peak_index, 200u);
  EXPECT_TRUE(r.peak_reached);
  EXPECT_NEAR(r.sigma_b_Pa, 0.1 * r.peak_stress_Pa, 1e-9 * r.peak_stress_Pa);
  EXPECT_NEAR(r.sigma_a_Pa, r.peak_stress_Pa / 3, 1e-9 * r.peak_stress_Pa);
  EXPECT_NEAR(r.E_secant_Pa / E, 1.0, 1e-12);
  EXPECT_NEAR(r.E_fit_Pa / E, 1.0, 1e-12);
  EXPECT_NEAR(*r.nu_secant, nu, 1e-12);
  EXPECT_NEAR(*r.nu_fit, nu, 1e-12);
  // I = eps_dot d sqrt(rho / sigma), largest at the lowest stress of the range (sigma_b).
  const double rate = 1e-5 / 1e-4;
  const double sigma_first = E * 1e-5 * std::ceil(0.1 * 200);
  EXPECT_NEAR(r.inertial_number_max, rate * 1.8e-3 * std::sqrt(2290 / sigma_first), 1e-9);
}

TEST(UniaxialTestAnalysis, RefusesWhatALabWouldRefuse) {
  const double area = 2.5e-3;
  const UniaxialTestSpecimen specimen{area, 1.8e-3, 2290};
  // A fast test: the inertial number above its bound.
  auto fast = known_curve(27e9, 0.16, 200, 260, area);
  for (auto& s : fast) s.dt_s = 1e-7;
  const std::string fast_error =
      mesowave::test::input_error_of([&] { analyse_uniaxial_test(fast, compression_spec(), specimen); });
  EXPECT_NE(fast_error.find("inertial number"), std::string::npos) << fast_error;
  // Absolute modulus levels above the peak.
  UniaxialTestSpec high = compression_spec();
  high.levels_absolute = true;
  high.levels[0] = 10e6;
  high.levels[1] = 100e6;
  EXPECT_THROW(analyse_uniaxial_test(known_curve(27e9, 0.16, 200, 260, area), high, specimen), InputError);
  // Extensometers that lengthen in a compression test (wrong axis or kind).
  auto wrong = known_curve(27e9, 0.16, 200, 260, area);
  for (double& v : wrong[1].samples) v = -v;
  EXPECT_THROW(analyse_uniaxial_test(wrong, compression_spec(), specimen), InputError);
  // A sensor the run did not record.
  UniaxialTestSpec missing = compression_spec();
  missing.axial = {"nowhere"};
  EXPECT_THROW(analyse_uniaxial_test(known_curve(27e9, 0.16, 200, 260, area), missing, specimen), InputError);
}

TEST(UniaxialTestMonitor, StopsAfterTheDropOnlyOnceArmed) {
  UniaxialTestSpec s = compression_spec();
  s.stop_drop = 0.2;
  s.stop_armed_above_Pa = 10e6;
  UniaxialTestMonitor m(s, 1.0);
  EXPECT_FALSE(m.stop_after({2e6}));
  EXPECT_FALSE(m.stop_after({1e6}));  // a 50 % drop below the arming stress: start-up noise
  EXPECT_FALSE(m.stop_after({50e6}));
  EXPECT_FALSE(m.stop_after({41e6}));
  EXPECT_TRUE(m.stop_after({39e6}));
  EXPECT_NE(m.reason().find("20 % below its peak 50 MPa"), std::string::npos) << m.reason();
}

TEST(SceneFiles, TestTablesAreChecked) {
  auto with_test = [](const std::string& test) {
    std::string text = kCompression;
    text = text.substr(0, text.find("[test]")) + test;
    return text;
  };
  EXPECT_NO_THROW(parse_scene(kCompression, "ok"));
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"[test]\nkind = \"shear\"\nload = [\"P_top\"]\naxial = [\"V\"]\n", "must be compression or tension"},
      {"[test]\nkind = \"compression\"\nload = [\"V\"]\naxial = [\"V\"]\n", "is not a force sensor"},
      {"[test]\nkind = \"compression\"\nload = [\"P_top\"]\naxial = [\"P_top\"]\n", "is not an extensometer"},
      {"[test]\nkind = \"compression\"\nload = [\"P_top\"]\naxial = [\"X\"]\n", "no sensor named \"X\""},
      {"[test]\nkind = \"compression\"\nload = [\"P_top\"]\naxial = [\"V\"]\nstop_drop_pct = 20\n", "needs stop_armed_above_MPa"},
      {"[test]\nkind = \"compression\"\nload = [\"P_top\"]\naxial = [\"V\"]\nmodulus_levels_pct = [40, 30]\n", "must rise"},
      {"[test]\nkind = \"compression\"\naxial = [\"V\"]\n", "needs load"},
  };
  for (const auto& [test, message] : bad) {
    const std::string error = mesowave::test::input_error_of([&] { parse_scene(with_test(test), "scene"); });
    EXPECT_NE(error.find(message), std::string::npos) << test << ": " << error;
  }
  // A wall covers its face: no patch, no direction.
  std::string patch_wall = kCompression;
  patch_wall.replace(patch_wall.find("face = \"z-\""), 11, "face = \"z-\"\ncentre_mm = [1, 1, 0]");
  EXPECT_THROW(parse_scene(patch_wall, "scene"), InputError);
}
