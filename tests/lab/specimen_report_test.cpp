// mw-specimen's report: one specimen in the user's units (g, mm) and a batch
// table, against densities and batch statistics worked out by hand.
#include "mesowave/lab/specimen_report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/input_error.hpp"

using namespace mesowave;
using namespace mesowave::lab;
using mesowave::test::input_error_of;

namespace {

TEST(SpecimenReport, OneCubeInGramsAndMillimetres) {
  SpecimenMeasurement m;
  m.mass_g = 7187.265;
  m.side_mm = 150;
  const auto j = specimen_density_summary(m);
  EXPECT_EQ(j["shape"], "cube");
  EXPECT_DOUBLE_EQ(j["side_mm"].get<double>(), 150);
  EXPECT_NEAR(j["volume_m3"].get<double>(), 0.15 * 0.15 * 0.15, 1e-15);
  EXPECT_NEAR(j["density_kg_m3"].get<double>(), 2129.56, 1e-9);  // concrete paper Section 3.1
  // GUM, rectangular: u = resolution / sqrt(12); V = a^3 so u_V / V = 3 u_a / a.
  const double rel = std::hypot(0.1 / std::sqrt(12.0) / 7187.265, 3 * 0.01 / std::sqrt(12.0) / 150);
  EXPECT_NEAR(j["u_density_kg_m3"].get<double>(), 2129.56 * rel, 1e-9);
  EXPECT_FALSE(j.contains("height_mm"));
}

TEST(SpecimenReport, OneCylinderNeedsItsDiameterAndHeight) {
  SpecimenMeasurement m;
  m.shape = "cylinder";
  m.mass_g = 3500;
  m.diameter_mm = 100;
  EXPECT_NE(input_error_of([&] { specimen_density_summary(m); }).find("a cylinder needs --height-mm"), std::string::npos);
  m.height_mm = 200;
  const auto j = specimen_density_summary(m);
  EXPECT_NEAR(j["density_kg_m3"].get<double>(), 3.5 / (std::numbers::pi / 4 * 0.1 * 0.1 * 0.2), 1e-9);
  m.mass_g.reset();
  EXPECT_NE(input_error_of([&] { specimen_density_summary(m); }).find("--mass-g is required"), std::string::npos);
}

TEST(SpecimenReport, BatchMeanAndSampleScatter) {
  // Two 100 mm cubes of 2.40 and 2.42 kg: 2400 and 2420 kg/m3, mean 2410,
  // sample standard deviation |2420 - 2400| / sqrt(2), standard error std / sqrt(2).
  const auto table = io::parse_csv("specimen,shape,mass_g,side_mm,note\nA,cube,2400,100,\nB,cube,2420,100,cast 2\n", "b.csv");
  const auto r = density_batch_report(table, {});
  EXPECT_EQ(r.summary["specimens"].get<int>(), 2);
  EXPECT_NEAR(r.summary["density_kg_m3"].get<double>(), 2410, 1e-9);
  EXPECT_NEAR(r.summary["density_std_kg_m3"].get<double>(), 20 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(r.summary["density_sem_kg_m3"].get<double>(), 10, 1e-9);
  EXPECT_NEAR(r.summary["density_min_kg_m3"].get<double>(), 2400, 1e-9);
  EXPECT_NEAR(r.summary["density_max_kg_m3"].get<double>(), 2420, 1e-9);
  const auto rows = io::parse_csv(r.table_csv, "out");
  ASSERT_EQ(rows.rows.size(), 2u);
  EXPECT_EQ(rows.header.front(), "specimen");
  EXPECT_EQ(rows.text(1, rows.column("specimen")), "B");
  EXPECT_EQ(rows.text(1, rows.column("density_kg_m3")), "2420.00");
  // Without a shape column every row has the defaults' shape, numbered from 1.
  SpecimenMeasurement prisms;
  prisms.shape = "prism";
  const auto p = density_batch_report(io::parse_csv("mass_g,length_mm,width_mm,height_mm\n9600,400,100,100\n", "p"), prisms);
  EXPECT_NEAR(p.summary["density_kg_m3"].get<double>(), 9.6 / 0.004, 1e-9);
  EXPECT_EQ(io::parse_csv(p.table_csv, "out").text(0, 1), "prism");
  EXPECT_EQ(io::parse_csv(p.table_csv, "out").text(0, 0), "1");
}

TEST(SpecimenReport, BatchErrorsNameTheFileAndLine) {
  EXPECT_NE(input_error_of([] { density_batch_report(io::parse_csv("specimen,mass_kg\nA,7\n", "b.csv"), {}); })
                .find("b.csv: unknown column 'mass_kg'"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { density_batch_report(io::parse_csv("mass_g,side_mm\n", "b.csv"), {}); }).find("no specimens"),
            std::string::npos);
  EXPECT_NE(input_error_of([] { density_batch_report(io::parse_csv("mass_g,side_mm\n7,150\n7,-1\n", "b.csv"), {}); })
                .find("b.csv:3: side_mm"),
            std::string::npos);
}

}  // namespace
