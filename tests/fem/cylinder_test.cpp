// mw-fem on an experiment's cylinder: the axisymmetric ring model of the rod, with the
// transducers mapped from the cylinder's frame - the run equals the rod case written out
// by hand (the second route to the same model), and what the rings cannot represent is
// refused with the reason.
#include <gtest/gtest.h>

#include "mesowave/experiment/experiment.hpp"
#include "mesowave/fem/case.hpp"
#include "support/input_error.hpp"

using namespace mesowave;

namespace {

std::string cylinder(const std::string& actuator_face, const std::string& actuator_centre,
                     const std::string& c_component = "normal") {
  return R"([specimen]
shape = "cylinder"
diameter_mm = { value = 20.0, source = "assumed", cite = "t" }
length_mm = { value = 100.0, source = "assumed", cite = "t" }
[[transducer]]
name = "A"
role = "actuator"
face = ")" + actuator_face + R"("
centre_mm = )" + actuator_centre + R"(
patch_mm = [3.0, 3.0]
source = "assumed"
cite = "t"
[[transducer]]
name = "B"
role = "sensor"
face = "z+"
centre_mm = [10.0, 10.0, 100.0]
patch_mm = [3.0, 3.0]
source = "assumed"
cite = "t"
[[transducer]]
name = "C"
role = "sensor"
face = "curved"
centre_mm = [20.0, 10.0, 50.0]
patch_mm = [3.0, 3.0]
component = ")" + c_component + R"("
source = "assumed"
cite = "t"
[burst]
frequency_kHz = { value = 100.0, source = "assumed", cite = "t" }
cycles = { value = 5.0, source = "assumed", cite = "t" }
amplitude_N = { value = 2.0, source = "assumed", cite = "t" }
[record]
duration_ms = { value = 0.04, source = "assumed", cite = "t" }
sample_interval_us = { value = 0.2, source = "assumed", cite = "t" }
)";
}

const fem::IsotropicMaterial kSteel{208.72e9, 0.3, 7850.66};

}  // namespace

TEST(FemCylinder, IsTheAxisymmetricRodWithTheTransducersMapped) {
  fem::FemCase c;
  c.material = kSteel;
  fem::apply_experiment(c, experiment::parse_experiment(cylinder("z-", "[10.0, 10.0, 0.0]"), "cyl.toml"));
  EXPECT_EQ(c.body, fem::FemCase::Body::rod);
  EXPECT_EQ(c.rod_model, "axisymmetric");
  EXPECT_DOUBLE_EQ(c.radius_m, 0.01);
  EXPECT_DOUBLE_EQ(c.length_m, 0.1);
  EXPECT_DOUBLE_EQ(c.force_N, 2.0);
  EXPECT_DOUBLE_EQ(c.duration_s, 4e-5);
  EXPECT_DOUBLE_EQ(c.sample_dt_s, 2e-7);
  ASSERT_EQ(c.probe_points.size(), 2u);
  EXPECT_EQ(c.probe_points[0].component, "z");  // the far end's outward normal
  EXPECT_EQ(c.probe_points[1].component, "r");  // the curved face's: radial
  EXPECT_DOUBLE_EQ(c.probe_points[1].position_m[0], 0.01);

  fem::FemCase by_hand;
  by_hand.material = kSteel;
  by_hand.radius_m = 0.01;
  by_hand.length_m = 0.1;
  by_hand.force_N = 2.0;
  by_hand.duration_s = 4e-5;
  by_hand.sample_dt_s = 2e-7;
  by_hand.patch_radius_m = std::sqrt(9e-6 / std::numbers::pi);
  by_hand.probe_points = {{"B", {0, 0, 0.1}, "z"}, {"C", {0.01, 0, 0.05}, "r"}};
  const fem::FemRun a = fem::run_fem_case(fem::assemble_fem_case(c));
  const fem::FemRun b = fem::run_fem_case(fem::assemble_fem_case(by_hand));
  ASSERT_EQ(a.result.signals.size(), b.result.signals.size());
  for (std::size_t i = 0; i < a.result.signals.size(); ++i) EXPECT_EQ(a.result.signals[i].samples, b.result.signals[i].samples);
  double peak = 0;
  for (double x : a.result.signals[0].samples) peak = std::max(peak, std::abs(x));
  EXPECT_GT(peak, 0.0);  // the pulse reached the far end within the record
}

TEST(FemCylinder, RefusesWhatTheRingsCannotRepresent) {
  using mesowave::test::input_error_of;
  auto error = [](const std::string& text) {
    return input_error_of([&] {
      fem::FemCase c;
      fem::apply_experiment(c, experiment::parse_experiment(text, "cyl.toml"));
    });
  };
  EXPECT_NE(error(cylinder("z-", "[14.0, 10.0, 0.0]")).find("actuator A on face z- at 4 mm from the axis: mw-fem models a "
                                                              "cylinder with axisymmetric rings"),
            std::string::npos);
  EXPECT_NE(error(cylinder("curved", "[10.0, 0.0, 50.0]")).find("need the load on the axis of the z- end"), std::string::npos);
  EXPECT_NE(error(cylinder("z-", "[10.0, 10.0, 0.0]", "x")).find("sensor C component x breaks the axial symmetry"),
            std::string::npos);
}
