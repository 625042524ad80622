// The HDF5 readers on files mesowave did not write: an attribute or dataset of
// another shape or type than the layout says is an InputError naming it - HDF5
// would otherwise convert into a buffer sized for one value (an overflow) or
// fail as an internal error (docs/fuzzing.md, crashes 1 and 2). And the piecewise
// writer against the whole one.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/io/hdf5.hpp"
#include "support/run_tool.hpp"
#include "support/input_error.hpp"

using namespace mesowave;
namespace h5 = io::h5;

namespace {

// An attribute of `n` float64 values, as h5py writes attrs["x"] = [...].
void add_doubles_attribute(hid_t object, const std::string& name, std::size_t n) {
  const hsize_t dims = n;
  const std::vector<double> values(n, 1.5);
  h5::Handle space(H5Screate_simple(1, &dims, nullptr));
  h5::Handle attr(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT));
  H5Awrite(attr.id(), H5T_NATIVE_DOUBLE, values.data());
}

}  // namespace

TEST(Hdf5Read, OneNumberIsOneValue) {
  test::TempDir dir;
  const auto path = dir.path() / "attributes.h5";
  {
    auto file = h5::create_file(path);
    add_doubles_attribute(file.id(), "one", 1);
    add_doubles_attribute(file.id(), "eight", 8);
    h5::set_attribute(file.id(), "text", std::string("1e-7"));
  }
  auto file = h5::open_file(path);
  EXPECT_EQ(h5::double_attribute(file.id(), "one"), 1.5);
  EXPECT_EQ(h5::doubles_attribute(file.id(), "eight").size(), 8u);  // a vector attribute takes any length
  EXPECT_EQ(test::input_error_of([&] { h5::double_attribute(file.id(), "eight"); }),
            "HDF5 attribute 'eight' holds 8 values where one is expected");
  EXPECT_EQ(test::input_error_of([&] { h5::double_attribute(file.id(), "text"); }), "HDF5 attribute 'text' is not numeric");
  EXPECT_EQ(test::input_error_of([&] { h5::doubles_attribute(file.id(), "text"); }), "HDF5 attribute 'text' is not numeric");
  EXPECT_EQ(test::input_error_of([&] { h5::string_attribute(file.id(), "one"); }), "HDF5 attribute 'one' is not a string");
}

TEST(Hdf5Read, AStringArrayIsNotOneString) {
  test::TempDir dir;
  const auto path = dir.path() / "strings.h5";
  {
    auto file = h5::create_file(path);
    h5::Handle type(H5Tcopy(H5T_C_S1));
    H5Tset_size(type.id(), 8);
    const hsize_t dims = 4;
    h5::Handle space(H5Screate_simple(1, &dims, nullptr));
    h5::Handle attr(H5Acreate2(file.id(), "names", type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT));
    H5Awrite(attr.id(), type.id(), std::string(32, 'a').data());
  }
  auto file = h5::open_file(path);
  EXPECT_EQ(test::input_error_of([&] { h5::string_attribute(file.id(), "names"); }),
            "HDF5 attribute 'names' holds 4 values where one is expected");
}

TEST(Hdf5Read, AStringDatasetIsNotNumbers) {
  test::TempDir dir;
  const auto path = dir.path() / "dataset.h5";
  {
    auto file = h5::create_file(path);
    h5::Handle type(H5Tcopy(H5T_C_S1));
    H5Tset_size(type.id(), 4);
    const hsize_t dims = 2;
    h5::Handle space(H5Screate_simple(1, &dims, nullptr));
    h5::Handle set(H5Dcreate2(file.id(), "samples", type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    H5Dwrite(set.id(), type.id(), H5S_ALL, H5S_ALL, H5P_DEFAULT, "abcdefgh");
    h5::write_doubles(file.id(), "numbers", {1, 2, 3});
  }
  auto file = h5::open_file(path);
  EXPECT_EQ(h5::read_doubles(file.id(), "numbers"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(test::input_error_of([&] { h5::read_doubles(file.id(), "samples"); }), "HDF5 dataset 'samples' is not numeric");
}

// Dimensions are header bytes: a dataset that claims far more than it stores
// is refused before gigabytes are allocated; a small unwritten one reads as its
// fill values, as HDF5 defines.
TEST(Hdf5Read, ADatasetMustStoreWhatItClaims) {
  test::TempDir dir;
  const auto path = dir.path() / "claims.h5";
  {
    auto file = h5::create_file(path);
    for (const auto& [name, n] : {std::pair{"small", hsize_t(10)}, std::pair{"huge", hsize_t(1) << 24}}) {
      const hsize_t dims = n;
      h5::Handle space(H5Screate_simple(1, &dims, nullptr));
      h5::Handle set(H5Dcreate2(file.id(), name, H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    }
  }
  auto file = h5::open_file(path);
  EXPECT_EQ(h5::read_doubles(file.id(), "small"), std::vector<double>(10, 0.0));
  EXPECT_EQ(test::input_error_of([&] { h5::read_doubles(file.id(), "huge"); }),
            "HDF5 dataset 'huge' claims 16777216 values but stores 0 bytes (a damaged file)");
}

// A distributed checkpoint's rank 0 writes each array a piece at a time (dem/engine/state_group.hpp):
// once every row is written, in any order of pieces, the file is the one the whole writers make,
// byte for byte (the MPI tests compare such checkpoints with one process's by cmp).
TEST(Hdf5Write, RowsWrittenInPiecesMakeTheWholeWritersFile) {
  test::TempDir dir;
  std::vector<double> xyz(3 * 1000);
  for (std::size_t k = 0; k < xyz.size(); ++k) xyz[k] = 0.001 * double(k) - 1.0;
  std::vector<std::int64_t> ids(777);
  for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = std::int64_t(k * k) - 300;
  {
    auto file = h5::create_file(dir.path() / "whole.h5");
    h5::write_doubles(file.id(), "xyz", xyz, 3);
    h5::write_int64s(file.id(), "ids", ids);
  }
  {
    auto file = h5::create_file(dir.path() / "pieces.h5");
    h5::RowWriter rows(file.id(), "xyz", 1000, 3, false);
    const auto piece = [&](std::size_t first, std::size_t end) {
      rows.write_rows(first, std::vector<double>(xyz.begin() + std::ptrdiff_t(3 * first), xyz.begin() + std::ptrdiff_t(3 * end)));
    };
    piece(500, 1000), piece(0, 97), piece(97, 500);
    EXPECT_THROW(rows.write_rows(999, std::vector<double>(6, 0.0)), std::logic_error);  // past the last row
    EXPECT_THROW(rows.write_rows(0, std::vector<double>(4, 0.0)), std::logic_error);    // not whole rows
    h5::RowWriter indices(file.id(), "ids", 777, 0, true);
    indices.write_rows(0, std::vector<std::int64_t>(ids.begin(), ids.begin() + 400));
    indices.write_rows(400, std::vector<std::int64_t>(ids.begin() + 400, ids.end()));
  }
  EXPECT_EQ(test::read_file(dir.path() / "whole.h5"), test::read_file(dir.path() / "pieces.h5"));
}
