// The experiment reader: a box and a cylinder read back with their values in SI, each
// transducer's outward normal (closed form: the face's axis, or radial on the curved face),
// the positions as fractions of the specimen and scaled; and every malformed file refused
// with one line naming the value.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "mesowave/core/error.hpp"
#include "mesowave/experiment/experiment.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::experiment;

namespace {

const std::string kBurst = R"(
[burst]
frequency_kHz = { value = 100.0, source = "paper", cite = "Section 4.1" }
cycles = { value = 5.0, source = "paper", cite = "Section 4.1" }
amplitude_N = { value = 0.01, source = "assumed", cite = "amplitude-free" }
[record]
duration_ms = { value = 1.5, source = "paper", cite = "Section 4.2" }
sample_interval_us = { value = 0.1, source = "assumed", cite = "10 MHz" }
)";

std::string transducer(const std::string& name, const std::string& role, const std::string& face,
                       const std::string& centre, const std::string& extra = "") {
  return "[[transducer]]\nname = \"" + name + "\"\nrole = \"" + role + "\"\nface = \"" + face + "\"\ncentre_mm = " + centre +
         "\npatch_mm = [3.0, 3.0]\n" + extra + "source = \"assumed\"\ncite = \"test\"\n";
}

const std::string kBox = R"([specimen]
shape = "box"
size_mm = { value = [50.0, 40.0, 30.0], source = "paper", cite = "Section 3.1" }
)" + transducer("A", "actuator", "x-", "[0.0, 20.0, 15.0]") +
                         transducer("B", "sensor", "x+", "[50.0, 20.0, 15.0]") +
                         transducer("E", "sensor", "z-", "[40.0, 20.0, 0.0]", "quantity = \"velocity\"\ncomponent = \"x\"\n");

const std::string kCylinder = R"([specimen]
shape = "cylinder"
diameter_mm = { value = 100.0, source = "assumed", cite = "UPV" }
length_mm = { value = 200.0, source = "assumed", cite = "UPV" }
)" + transducer("A", "actuator", "z-", "[50.0, 50.0, 0.0]") +
                              transducer("B", "sensor", "z+", "[50.0, 50.0, 200.0]") +
                              transducer("C", "sensor", "curved", "[85.35533905932738, 85.35533905932738, 100.0]");

}  // namespace

TEST(Experiment, ReadsABoxInSIUnits) {
  const Experiment e = parse_experiment(kBox + kBurst, "box.toml");
  EXPECT_EQ(e.specimen.shape, Specimen::Shape::box);
  EXPECT_DOUBLE_EQ(e.specimen.size_m[1], 0.04);
  ASSERT_EQ(e.transducers.size(), 3u);
  ASSERT_EQ(e.actuators().size(), 1u);
  ASSERT_EQ(e.sensors().size(), 2u);
  EXPECT_EQ(e.transducers[2].quantity, MotionQuantity::velocity);
  EXPECT_EQ(e.transducers[2].component, "x");
  EXPECT_DOUBLE_EQ(e.transducers[1].centre_m[0], 0.05);
  EXPECT_DOUBLE_EQ(e.transducers[0].patch_m[1], 3e-3);
  EXPECT_EQ(e.transducers[0].source, "assumed");
  EXPECT_DOUBLE_EQ(e.burst.frequency_hz, 100e3);
  EXPECT_DOUBLE_EQ(e.burst.amplitude_N, 0.01);
  EXPECT_DOUBLE_EQ(e.burst.delay_s, 0.0);
  EXPECT_DOUBLE_EQ(e.record.duration_s, 1.5e-3);
  EXPECT_DOUBLE_EQ(e.record.sample_interval_s, 1e-7);
  EXPECT_EQ(e.specimen.describe(), "50 x 40 x 30 mm box");
}

TEST(Experiment, NormalsRelativePositionsAndScaling) {
  const Experiment box = parse_experiment(kBox + kBurst, "box.toml");
  EXPECT_EQ(outward_normal(box.specimen, box.transducers[0]), (std::array<double, 3>{-1, 0, 0}));
  EXPECT_EQ(outward_normal(box.specimen, box.transducers[2]), (std::array<double, 3>{0, 0, -1}));
  const auto rel = relative_position(box.specimen, box.transducers[2].centre_m);
  EXPECT_EQ(rel[0], 0.8);  // 40 / 50 exactly as written: the DEM scene's fractions of the cube
  EXPECT_EQ(rel[1], 0.5);
  EXPECT_EQ(rel[2], 0.0);
  const Experiment small = scaled(box, 0.4);
  EXPECT_EQ(small.specimen.size_m[0], 20 * 1e-3);
  EXPECT_EQ(small.transducers[2].centre_m[0], 16 * 1e-3);
  EXPECT_EQ(small.transducers[2].patch_m[0], 3e-3);  // the transducer keeps its size
  EXPECT_NEAR(patch_disc_radius_m(box.transducers[0]), std::sqrt(9e-6 / std::numbers::pi), 1e-18);

  const Experiment cyl = parse_experiment(kCylinder + kBurst, "cyl.toml");
  EXPECT_EQ(cyl.specimen.describe(), "100 x 200 mm cylinder");
  EXPECT_DOUBLE_EQ(cyl.specimen.radius_m(), 0.05);
  EXPECT_DOUBLE_EQ(cyl.specimen.length_m(), 0.2);
  EXPECT_EQ(outward_normal(cyl.specimen, cyl.transducers[1]), (std::array<double, 3>{0, 0, 1}));
  const auto n = outward_normal(cyl.specimen, cyl.transducers[2]);  // 45 degrees: radial
  EXPECT_NEAR(n[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(n[1], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(azimuth(cyl.specimen, cyl.transducers[2].centre_m), std::numbers::pi / 4, 1e-12);
}

TEST(Experiment, RefusesMalformedFilesNamingTheValue) {
  using mesowave::test::input_error_of;
  auto error = [](const std::string& text) { return input_error_of([&] { parse_experiment(text, "x.toml"); }); };
  EXPECT_NE(error(kBox + kBurst + "[extra]\n").find("unknown section [extra]"), std::string::npos);
  EXPECT_NE(error(kBox + kBurst + "[[transducer]]\nname = \"B\"\nrole = \"sensor\"\nface = \"x+\"\ncentre_mm = [50.0, 1.0, 1.0]\n"
                                  "patch_mm = [3.0, 3.0]\nsource = \"assumed\"\ncite = \"t\"\n")
                .find("the name \"B\" is used twice"),
            std::string::npos);
  std::string no_cite = kBox + kBurst;
  no_cite.replace(no_cite.find(", cite = \"Section 3.1\""), 22, "");
  EXPECT_NE(error(no_cite).find("[specimen].size_mm (source \"paper\") needs cite"), std::string::npos);
  std::string bare = kBox + kBurst;
  const std::string sourced = "{ value = 0.01, source = \"assumed\", cite = \"amplitude-free\" }";
  bare.replace(bare.find(sourced), sourced.size(), "0.01");
  EXPECT_NE(error(bare).find("[burst].amplitude_N must be a table {value"), std::string::npos);
  EXPECT_NE(error(R"([specimen]
shape = "box"
size_mm = { value = [50.0, 50.0, 50.0], source = "paper", cite = "c" }
)" + transducer("A", "actuator", "x-", "[1.0, 20.0, 15.0]") + kBurst)
                .find("(A).centre_mm (1, 20, 15) mm is not on face x- (x = 0 mm)"),
            std::string::npos);
  EXPECT_NE(error(kBox + transducer("C", "sensor", "curved", "[50.0, 20.0, 15.0]") + kBurst)
                .find("face \"curved\" needs a cylinder specimen"),
            std::string::npos);
  EXPECT_NE(error(kCylinder + transducer("X", "sensor", "x+", "[100.0, 50.0, 10.0]") + kBurst)
                .find("a cylinder's faces are z- and z+ (its ends) and curved"),
            std::string::npos);
  EXPECT_NE(error(kCylinder + transducer("X", "sensor", "curved", "[90.0, 50.0, 10.0]") + kBurst)
                .find("is not on the curved face (40 mm from the axis, radius 50 mm)"),
            std::string::npos);
  EXPECT_NE(error(kCylinder + transducer("X", "sensor", "z-", "[99.0, 99.0, 0.0]") + kBurst)
                .find("lies outside the cylinder's end face"),
            std::string::npos);
  EXPECT_NE(error(kBox + transducer("S", "sensor", "y+", "[1.0, 40.0, 1.0]", "quantity = \"strain\"\n") + kBurst)
                .find("(S).quantity (\"strain\") must be acceleration, velocity or displacement"),
            std::string::npos);
  std::string sensors_only = kBox + kBurst;
  sensors_only.replace(sensors_only.find("role = \"actuator\""), 17, "role = \"sensor\"");
  EXPECT_NE(error(sensors_only).find("needs at least one actuator and one sensor (found 0 and 3)"), std::string::npos);
  EXPECT_NE(input_error_of([] { read_experiment_file("/nonexistent/experiment.toml"); })
                .find("experiment file /nonexistent/experiment.toml cannot be read"),
            std::string::npos);
}

// lab-data/steel-rod/experiment.toml against the rod paper (Section 4.1: D = 10.2 mm, l = 1000 mm,
// rho = 7850.66 kg/m3, E = 208.72 GPa, nu = 0.3; Section 4.2: A and S on the two ends, a five-cycle
// burst; Sections 4.3.1-4.3.2: 1.5 ms, the FEM's 1e-7 s step), read as the rod every rod tool takes.
TEST(Experiment, TheSteelRodIsTheRodPapers) {
  const Experiment e = read_experiment_file(std::filesystem::path(MESOWAVE_SOURCE_DIR) / "lab-data/steel-rod/experiment.toml");
  const Rod rod = rod_of(e);
  EXPECT_EQ(rod.radius_m, 5.1 * 1e-3);  // R = D / 2 (Section 4.3.2) to the bit, as --radius-mm 5.1 gives it
  EXPECT_EQ(rod.length_m, 1.0);
  EXPECT_EQ(rod.E_Pa, 208.72e9);
  EXPECT_EQ(rod.nu, 0.3);
  EXPECT_EQ(rod.density_kg_m3, 7850.66);
  EXPECT_EQ(e.specimen.describe(), "10.2 x 1000 mm cylinder");
  ASSERT_EQ(e.actuators().size(), 1u);
  ASSERT_EQ(e.sensors().size(), 1u);
  const Transducer& a = *e.actuators().front();
  const Transducer& s = *e.sensors().front();
  EXPECT_EQ(a.name, "A");
  EXPECT_EQ(s.name, "S");
  EXPECT_EQ(a.face, "z-");
  EXPECT_EQ(s.face, "z+");
  EXPECT_EQ(a.patch_m[0], 2e-3);  // the Noliac NAC2011 plate, 2 x 2 x 2 mm
  EXPECT_EQ(outward_normal(e.specimen, s), (std::array<double, 3>{0, 0, 1}));
  EXPECT_EQ(relative_position(e.specimen, a.centre_m), (std::array<double, 3>{0.5, 0.5, 0.0}));  // on the axis
  EXPECT_EQ(relative_position(e.specimen, s.centre_m), (std::array<double, 3>{0.5, 0.5, 1.0}));
  EXPECT_EQ(s.quantity, MotionQuantity::acceleration);
  EXPECT_EQ(e.burst.cycles, 5.0);
  EXPECT_EQ(e.burst.frequency_hz, 100e3);
  EXPECT_EQ(e.record.duration_s, 1.5e-3);
  EXPECT_EQ(e.record.sample_interval_s, 1e-7);
}

TEST(Experiment, ARodAtAnotherLengthKeepsItsEndsAndRefusesWhatIsNotARod) {
  using mesowave::test::input_error_of;
  const Experiment cyl = parse_experiment(kCylinder + kBurst, "cyl.toml");
  const Experiment half = with_length(cyl, 0.1);
  EXPECT_EQ(half.specimen.length_m(), 0.1);
  EXPECT_EQ(half.specimen.size_m[0], cyl.specimen.size_m[0]);  // the diameter kept
  EXPECT_EQ(half.transducers[0].centre_m[2], 0.0);             // the ends stay the ends, exactly
  EXPECT_EQ(half.transducers[1].centre_m[2], 0.1);
  EXPECT_EQ(half.transducers[2].centre_m[2], 0.05);            // mid-height stays mid-height
  EXPECT_EQ(half.transducers[2].centre_m[0], cyl.transducers[2].centre_m[0]);
  const Experiment box = parse_experiment(kBox + kBurst, "box.toml");
  EXPECT_NE(input_error_of([&] { with_length(box, 0.1); }).find("only a cylinder's length can be changed alone"), std::string::npos);
  EXPECT_NE(input_error_of([&] { with_length(cyl, 0.0); }).find("the rod length (0 mm) must be"), std::string::npos);
  EXPECT_NE(input_error_of([&] { rod_of(box); }).find("a rod is a cylinder specimen, this one is a 50 x 40 x 30 mm box"),
            std::string::npos);
  std::string with_E = kCylinder;
  with_E.insert(with_E.find("[[transducer]]"), "E_GPa = { value = 200.0, source = \"assumed\", cite = \"steel\" }\n");
  EXPECT_NE(input_error_of([&] { rod_of(parse_experiment(with_E + kBurst, "rod.toml")); })
                .find("[specimen] needs nu density_kg_m3 for a rod"),
            std::string::npos);
}
