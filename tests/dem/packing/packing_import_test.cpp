// Importing packings made elsewhere (CSV with units, Yade textExt) and
// exporting ours: exact round trips and clear errors.
#include <gtest/gtest.h>

#include <filesystem>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/packing/packing_generator.hpp"
#include "mesowave/dem/packing/packing_import.hpp"
#include "mesowave/dem/packing/packing_stats.hpp"
#include "support/input_error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using namespace mesowave::dem;

namespace {

Packing sample() {
  Packing p;
  p.centres_m = {{0.1 / 3, 1e-3, 2.5e-2}, {4.999999999999999e-2, 0.0012345678901234567, 7e-3}, {1e-3, 2e-3, 3e-3}};
  p.radii_m = {0.8e-3, 1.0000000000000002e-3, 0.9e-3};
  p.ids = {0, 1, 2};
  p.container = box_container({0, 0, 0}, {50e-3, 50e-3, 50e-3});
  return p;
}

void expect_same_spheres(const Packing& a, const Packing& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.centres_m[i], b.centres_m[i]) << i;
    EXPECT_EQ(a.radii_m[i], b.radii_m[i]) << i;
  }
}

}  // namespace

TEST(PackingImport, YadeTextRoundTripIsExact) {
  const auto p = sample();
  const auto text = yade_text(p, "made by a test\nsecond line");
  EXPECT_EQ(text.rfind("#format x_y_z_r\n# made by a test\n# second line\n", 0), 0u);
  expect_same_spheres(parse_yade_text(text, "t.txt"), p);
}

TEST(PackingImport, YadeTextAsYadeWritesIt) {
  // yade.export.textExt: "#format x_y_z_r", comment lines, tab-separated %g numbers.
  const std::string text =
      "#format x_y_z_r\n# a comment\n0.01\t0.02\t0.03\t0.001\n\n  0.011 0.02 0.03 0.0009  \n";
  const auto p = parse_yade_text(text, "yade.txt");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p.centres_m[1][0], 0.011);
  EXPECT_EQ(p.radii_m[1], 0.0009);
  EXPECT_EQ(p.ids, (std::vector<std::int64_t>{0, 1}));
  // Other layouts Yade reads: a material id after r, or an id before x.
  const auto m = parse_yade_text("#format x_y_z_r_matId\n1 2 3 0.5 7\n", "m.txt");
  EXPECT_EQ(m.radii_m[0], 0.5);
  const auto i = parse_yade_text("#format id_x_y_z_r_matId\n9 1 2 3 0.5 7\n", "i.txt");
  EXPECT_EQ(i.centres_m[0][0], 1.0);
  EXPECT_EQ(i.radii_m[0], 0.5);
}

TEST(PackingImport, MalformedYadeText) {
  EXPECT_THROW(parse_yade_text("# nothing\n", "a"), InputError);
  EXPECT_THROW(parse_yade_text("1 2 3\n", "a"), InputError);
  EXPECT_THROW(parse_yade_text("1 2 3 x\n", "a"), InputError);
  EXPECT_THROW(parse_yade_text("1 2 3 -0.5\n", "a"), InputError);
  EXPECT_THROW(parse_yade_text("1 2 3 0\n", "a"), InputError);
  EXPECT_THROW(parse_yade_text("#format x_y_z\n1 2 3 1\n", "a"), InputError);
  EXPECT_THROW(parse_yade_text("1 2 nan 1\n", "a"), InputError);
  EXPECT_EQ(mesowave::test::input_error_of([] { parse_yade_text("0 0 0 1\n1 2 3 x\n", "spheres.txt"); }),
            "spheres.txt:2: 'x' is not a finite number");
}

TEST(PackingImport, CsvWithUnitsInTheColumnNames) {
  const auto mm = parse_packing_csv("x_mm,y_mm,z_mm,r_mm\n1,2,3,0.8\n4,5,6,1\n", "a.csv");
  ASSERT_EQ(mm.size(), 2u);
  EXPECT_DOUBLE_EQ(mm.centres_m[1][2], 6e-3);
  EXPECT_DOUBLE_EQ(mm.radii_m[0], 0.8e-3);
  const auto diameters = parse_packing_csv("id,x_m,y_m,z_m,d_um,colour\n7,0.001,0.002,0.003,1600,red\n", "b.csv");
  EXPECT_EQ(diameters.ids, (std::vector<std::int64_t>{7}));
  EXPECT_DOUBLE_EQ(diameters.radii_m[0], 0.8e-3);
  // Our CSV export reads back exactly.
  const auto p = sample();
  const auto back = parse_packing_csv(packing_csv(p), "ours.csv");
  expect_same_spheres(back, p);
  EXPECT_EQ(back.ids, p.ids);
}

TEST(PackingImport, MalformedCsv) {
  EXPECT_THROW(parse_packing_csv("x,y,z,r\n1,2,3,1\n", "a"), InputError);  // no units
  EXPECT_THROW(parse_packing_csv("x_mm,y_mm,z_mm\n1,2,3\n", "a"), InputError);
  EXPECT_THROW(parse_packing_csv("x_mm,y_mm,z_mm,r_mm\n", "a"), InputError);  // no spheres
  EXPECT_THROW(parse_packing_csv("x_mm,y_mm,z_mm,r_mm\n1,2,3,-1\n", "a"), InputError);
  EXPECT_THROW(parse_packing_csv("x_mm,y_mm,z_mm,r_mm\n1,2,3\n", "a"), InputError);
  EXPECT_THROW(parse_packing_csv("id,x_mm,y_mm,z_mm,r_mm\n1,1,2,3,1\n1,1,2,3,1\n", "a"), InputError);  // duplicate id
  EXPECT_THROW(parse_packing_csv("id,x_mm,y_mm,z_mm,r_mm\n1.5,1,2,3,1\n", "a"), InputError);
}

TEST(PackingImport, PackingFileRoundTripWithOrigin) {
  test::TempDir dir;
  auto p = sample();
  p.particle_density_kg_m3 = 2289.87;
  PackingOrigin origin;
  origin.text = {{"method", "test"}, {"seed", "18446744073709551615"}};
  origin.numbers = {{"target_porosity", 0.07}};
  write_packing_file(dir / "p.h5", p, origin);
  const auto back = read_packing_file(dir / "p.h5");
  expect_same_spheres(back, p);
  EXPECT_EQ(back.ids, p.ids);
  EXPECT_EQ(back.container.shape, "box");
  EXPECT_EQ(back.container.upper_m, p.container.upper_m);
  EXPECT_EQ(back.particle_density_kg_m3, 2289.87);
  const auto o = read_packing_origin(dir / "p.h5");
  ASSERT_EQ(o.text.size(), 2u);
  EXPECT_EQ(o.text[0].first, "method");
  EXPECT_EQ(o.text[1].second, "18446744073709551615");
  ASSERT_EQ(o.numbers.size(), 1u);
  EXPECT_EQ(o.numbers[0].second, 0.07);
  // A file without /origin reads as an empty origin.
  write_packing_file(dir / "plain.h5", p);
  EXPECT_TRUE(read_packing_origin(dir / "plain.h5").empty());
}

// An MPI rank's share (docs/mpi.md): part r of N is rows [n r / N, n (r + 1) / N), read as a
// hyperslab, the attributes whole; the parts in order are the file.
TEST(PackingImport, APackingFileReadInPartsIsTheFileInOrder) {
  test::TempDir dir;
  Packing p;
  for (int i = 0; i < 7; ++i) {
    p.centres_m.push_back({1e-3 * i, 2e-3 * i + 1e-17, 3e-3});
    p.radii_m.push_back(0.5e-3 + 1e-5 * i);
    p.ids.push_back(100 + i);
  }
  p.container = box_container({0, 0, 0}, {10e-3, 20e-3, 5e-3});
  p.particle_density_kg_m3 = 2400;
  write_packing_file(dir / "p.h5", p);
  const std::size_t expected_first[] = {0, 2, 4}, expected_size[] = {2, 2, 3};  // 7 rows in 3 parts
  Packing joined;
  for (int part = 0; part < 3; ++part) {
    const Packing piece = read_packing_file(dir / "p.h5", part, 3);
    EXPECT_TRUE(piece.is_piece());
    EXPECT_EQ(piece.first_row, expected_first[part]);
    EXPECT_EQ(piece.file_rows, 7u);
    EXPECT_EQ(piece.size(), expected_size[part]);
    EXPECT_EQ(piece.container.upper_m, p.container.upper_m);
    EXPECT_EQ(piece.particle_density_kg_m3, 2400);
    joined.centres_m.insert(joined.centres_m.end(), piece.centres_m.begin(), piece.centres_m.end());
    joined.radii_m.insert(joined.radii_m.end(), piece.radii_m.begin(), piece.radii_m.end());
    joined.ids.insert(joined.ids.end(), piece.ids.begin(), piece.ids.end());
  }
  expect_same_spheres(joined, p);
  EXPECT_EQ(joined.ids, p.ids);
  EXPECT_FALSE(read_packing_file(dir / "p.h5").is_piece());
}

TEST(PackingImport, BoundingBox) {
  const auto b = bounding_box(sample());
  EXPECT_DOUBLE_EQ(b.lower_m[0], 1e-3 - 0.9e-3);
  EXPECT_DOUBLE_EQ(b.upper_m[0], 4.999999999999999e-2 + 1.0000000000000002e-3);
  EXPECT_DOUBLE_EQ(b.upper_m[2], 2.5e-2 + 0.8e-3);
}
