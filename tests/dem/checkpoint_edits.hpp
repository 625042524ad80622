#pragma once
// Checkpoints damaged on purpose, for the tests that a restart refuses them (dem.Checkpoint, and
// cli.MwDemMpi on several ranks): the law's first slot given the bond index of the last bonded
// slot, so that bond is in two slots and the first slot's own bond in none; or a contact's sphere
// past the packing's. Every other array is left as written, so only one check can tell.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace mesowave::test {

inline void give_the_first_slot_the_last_bond(const std::filesystem::path& checkpoint) {
  const hid_t f = H5Fopen(checkpoint.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0) << checkpoint;
  const hid_t d = H5Dopen2(f, "/model/law/bond", H5P_DEFAULT);
  ASSERT_GE(d, 0) << checkpoint;
  const hid_t space = H5Dget_space(d);
  std::vector<std::uint32_t> bond(std::size_t(H5Sget_simple_extent_npoints(space)));
  ASSERT_GE(H5Dread(d, H5T_NATIVE_UINT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, bond.data()), 0);
  std::size_t last = bond.size() - 1;
  while (bond[last] == 0xffffffffu) --last;  // no bond (a detected pair)
  ASSERT_NE(bond[0], bond[last]);
  bond[0] = bond[last];
  ASSERT_GE(H5Dwrite(d, H5T_NATIVE_UINT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, bond.data()), 0);
  H5Sclose(space), H5Dclose(d), H5Fclose(f);
}

/// The law's contact list with row `row`'s second sphere set to `sphere` (one that no packing of
/// fewer spheres has): a restart must find that the contacts do not fit.
inline void set_a_contacts_second_sphere(const std::filesystem::path& checkpoint, std::size_t row, std::int64_t sphere) {
  const hid_t f = H5Fopen(checkpoint.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0) << checkpoint;
  const hid_t d = H5Dopen2(f, "/model/law/second", H5P_DEFAULT);
  ASSERT_GE(d, 0) << checkpoint;
  const hid_t space = H5Dget_space(d);
  std::vector<std::int64_t> second(std::size_t(H5Sget_simple_extent_npoints(space)));
  ASSERT_LT(row, second.size());
  ASSERT_GE(H5Dread(d, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, second.data()), 0);
  second[row] = sphere;
  ASSERT_GE(H5Dwrite(d, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, second.data()), 0);
  H5Sclose(space), H5Dclose(d), H5Fclose(f);
}

}  // namespace mesowave::test
