// StateGroup's piecewise reads (state_group.hpp): what a rank of a distributed restart takes of a
// checkpoint's arrays. The reference is the whole array read at once, on arrays longer than one
// piece (StateGroup::kPieceRows), so that the rows come from several hyperslabs.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/engine/state_group.hpp"
#include "mesowave/io/hdf5.hpp"
#include "support/input_error.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using mesowave::dem::StateGroup;
using mesowave::dem::Vec3;

namespace {

constexpr std::size_t kRows = 2 * StateGroup::kPieceRows + 1000;

void write_arrays(const std::filesystem::path& path) {
  io::h5::Handle f = io::h5::create_file(path);
  StateGroup root(H5Gopen2(f.id(), "/", H5P_DEFAULT), path.string() + ":/");
  std::vector<double> values(kRows);
  std::vector<Vec3> vectors(kRows);
  std::vector<std::uint32_t> indices(kRows);
  for (std::size_t k = 0; k < kRows; ++k) {
    values[k] = 0.5 + double(k) * 1e-3;
    vectors[k] = {double(k), -double(k), 1.0 / double(k + 1)};
    indices[k] = std::uint32_t(7 * k + 3);
  }
  root.write("values", values);
  root.write("vectors", vectors);
  root.write("indices", indices);
}

// The file's root group, as a checkpoint's is read.
struct Written {
  test::TempDir dir;
  io::h5::Handle file;
  StateGroup root;
  Written() : file(write_and_open(dir.path() / "state.h5")), root(H5Gopen2(file.id(), "/", H5P_DEFAULT), "state.h5:/") {}
  static io::h5::Handle write_and_open(const std::filesystem::path& path) {
    write_arrays(path);
    return io::h5::open_file(path);
  }
};

}  // namespace

TEST(StateGroup, RowsAtAscendingIndicesAreTheWholeArraysRowsAcrossPieces) {
  const Written written;
  const StateGroup& root = written.root;
  const std::vector<double> values = root.read_doubles("values");
  const std::vector<std::uint32_t> indices = root.read_uint32s("indices");
  // The first and last rows, both sides of each piece's end, a run, and gaps wider than a piece.
  const std::vector<std::uint32_t> at = {0,
                                         1,
                                         2,
                                         std::uint32_t(StateGroup::kPieceRows - 1),
                                         std::uint32_t(StateGroup::kPieceRows),
                                         std::uint32_t(StateGroup::kPieceRows + 1),
                                         std::uint32_t(2 * StateGroup::kPieceRows + 5),
                                         std::uint32_t(kRows - 1)};
  const auto got = root.read_at("values", kRows, at);
  const auto got_vectors = root.read_vec3s_at("vectors", kRows, at);
  const auto got_indices = root.read_uint32s_at("indices", kRows, at);
  ASSERT_EQ(got.size(), at.size());
  ASSERT_EQ(got_vectors.size(), at.size());
  ASSERT_EQ(got_indices.size(), at.size());
  for (std::size_t i = 0; i < at.size(); ++i) {
    EXPECT_EQ(got[i], values[at[i]]) << at[i];
    EXPECT_EQ(got_vectors[i].x, double(at[i])) << at[i];
    EXPECT_EQ(got_vectors[i].y, -double(at[i])) << at[i];
    EXPECT_EQ(got_vectors[i].z, 1.0 / double(at[i] + 1)) << at[i];
    EXPECT_EQ(got_indices[i], indices[at[i]]) << at[i];
  }
  // Every row: the whole array.
  std::vector<std::uint32_t> all(kRows);
  for (std::size_t k = 0; k < kRows; ++k) all[k] = std::uint32_t(k);
  EXPECT_EQ(root.read_at("values", kRows, all), values);
  EXPECT_TRUE(root.read_at("values", kRows, {}).empty());
  // A range of an index array, and its length.
  std::size_t rows = 0;
  const auto range = root.read_uint32s("indices", StateGroup::kPieceRows - 2, 4, &rows);
  EXPECT_EQ(rows, kRows);
  EXPECT_EQ(range, std::vector<std::uint32_t>(indices.begin() + std::ptrdiff_t(StateGroup::kPieceRows - 2),
                                              indices.begin() + std::ptrdiff_t(StateGroup::kPieceRows + 2)));
}

TEST(StateGroup, APieceOfAnotherRunsArrayIsRefused) {
  const Written written;
  const StateGroup& root = written.root;
  EXPECT_EQ(test::input_error_of([&] { root.read_at("values", kRows + 1, {0}); }),
            "checkpoint state.h5:/values holds " + std::to_string(kRows) + " rows, this run " + std::to_string(kRows + 1) +
                ": the checkpoint is not from this run");
  // Vectors are rows of three; values are not.
  EXPECT_NE(test::input_error_of([&] { root.read_vec3s_at("values", kRows, {0}); }), "");
  EXPECT_NE(test::input_error_of([&] { root.read_at("vectors", kRows, {0}); }), "");
  EXPECT_NE(test::input_error_of([&] { root.read_at("missing", kRows, {0}); }).find("is missing"), std::string::npos);
  EXPECT_NE(test::input_error_of([&] { root.read_uint32s("indices", kRows - 1, 2); }), "");
  // Rows past the end or out of order are the caller's error, not the file's.
  EXPECT_THROW(root.read_at("values", kRows, {3, 2}), std::logic_error);
  EXPECT_THROW(root.read_at("values", kRows, {std::uint32_t(kRows)}), std::logic_error);
}
