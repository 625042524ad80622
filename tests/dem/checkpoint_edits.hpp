#pragma once
// Checkpoints damaged on purpose, for the tests that a restart refuses them (dem.Checkpoint, and
// cli.MwDemMpi on several ranks): the law's first slot given the bond index of the last bonded
// slot, so that bond is in two slots and the first slot's own bond in none; or a contact's sphere
// past the packing's, or not an index at all. Every other array is left as written, so only one
// check can tell.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::test {

/// The law's index array `name` (int64 in the file) read whole, changed by edit(values), and
/// written back.
template <class Edit>
void edit_law_indices(const std::filesystem::path& checkpoint, const std::string& name, const Edit& edit) {
  const hid_t f = H5Fopen(checkpoint.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0) << checkpoint;
  const hid_t d = H5Dopen2(f, ("/model/law/" + name).c_str(), H5P_DEFAULT);
  ASSERT_GE(d, 0) << checkpoint << ": " << name;
  const hid_t space = H5Dget_space(d);
  std::vector<std::int64_t> values(std::size_t(H5Sget_simple_extent_npoints(space)));
  ASSERT_GE(H5Dread(d, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  edit(values);
  // An ASSERT inside edit ends edit alone: then nothing is written back (the test fails anyway).
  const bool edited = !::testing::Test::HasFatalFailure();
  const herr_t written = edited ? H5Dwrite(d, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) : 0;
  H5Sclose(space), H5Dclose(d), H5Fclose(f);
  ASSERT_GE(written, 0) << checkpoint << ": " << name;
}

inline void give_the_first_slot_the_last_bond(const std::filesystem::path& checkpoint) {
  edit_law_indices(checkpoint, "bond", [](std::vector<std::int64_t>& bond) {
    std::size_t last = bond.size() - 1;
    while (bond[last] == 0xffffffff) --last;  // no bond (a detected pair)
    ASSERT_NE(bond[0], bond[last]);
    bond[0] = bond[last];
  });
}

/// The law's contact list with row `row`'s sphere `end` ("first" or "second") set to `sphere`:
/// one that no packing of fewer spheres has, or a value that is no index. A restart must refuse it.
inline void set_a_contacts_end(const std::filesystem::path& checkpoint, const std::string& end, std::size_t row,
                               std::int64_t sphere) {
  edit_law_indices(checkpoint, end, [&](std::vector<std::int64_t>& spheres) {
    ASSERT_LT(row, spheres.size());
    spheres[row] = sphere;
  });
}

}  // namespace mesowave::test
