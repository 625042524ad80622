// The HDF5 readers on files mesowave did not write: an attribute or dataset of
// another shape or type than the layout says is an InputError naming it - HDF5
// would otherwise convert into a buffer sized for one value (an overflow) or
// fail as an internal error (docs/fuzzing.md, crashes 1 and 2).
#include <gtest/gtest.h>

#include <functional>
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
