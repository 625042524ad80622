#pragma once
// What a DEM run carries from step to step, saved and read back exactly so that
// a run restarted from a checkpoint (checkpoint.hpp) continues to the same bits
// as an uninterrupted one. Each stateful part of a run - the model (positions,
// velocities, energies), its contact law (bonds broken, shear forces, the
// contact list), each actuator and each sensor (the samples so far) - writes its
// own state to a group of the checkpoint file and reads it from there, through
// save_state / load_state (Model, ContactKernel, Actuator, Sensor); the engine
// knows no kind. Numbers are stored binary (float64 for doubles, int64 for
// counts and indices), never as text, so every double comes back bit for bit.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesowave/core/error.hpp"
#include "mesowave/dem/engine/vec3.hpp"

namespace mesowave::io::h5 {
class RowWriter;
}

namespace mesowave::dem {

/// One group of a checkpoint file (an HDF5 group; the id is an HDF5 hid_t,
/// kept as int64 so that this header does not include HDF5). A read of a
/// missing value, or of an array of another size than the run's, is an
/// InputError naming the value and the file: the checkpoint is from another run.
class StateGroup {
public:
  StateGroup(std::int64_t hdf5_id, std::string where) : id_(hdf5_id), where_(std::move(where)) {}
  ~StateGroup();
  /// A group that writes nothing (nor do its sub-groups): on a distributed run the ranks but 0
  /// save their state through it, so that they take part in the gathers of what rank 0 writes.
  static StateGroup nowhere() { return StateGroup(-1, ""); }
  StateGroup(StateGroup&& other) noexcept : id_(other.id_), where_(std::move(other.where_)) { other.id_ = -1; }
  StateGroup(const StateGroup&) = delete;
  StateGroup& operator=(const StateGroup&) = delete;

  /// A sub-group: created (writing) or opened (reading; InputError if missing).
  StateGroup create(const std::string& name);
  StateGroup open(const std::string& name) const;

  void write(const std::string& name, double value);
  void write(const std::string& name, std::int64_t value);
  void write(const std::string& name, const std::vector<double>& values);
  void write(const std::string& name, const std::vector<Vec3>& values);
  void write(const std::string& name, const std::vector<std::uint32_t>& values);

  /// An array of `rows` rows of `cols` doubles (0: 1-D), or of indices (stored as write() stores
  /// them), written a piece at a time as the pieces come: once every row is written, the file
  /// holds what write() would have written whole. What a distributed checkpoint's rank 0 writes
  /// as the ranks send it, never holding the array whole. A group that writes nowhere gives a
  /// writer that writes nothing.
  class Rows {
  public:
    explicit Rows(std::unique_ptr<io::h5::RowWriter> writer, bool indices);
    Rows(Rows&&) noexcept;
    ~Rows();
    /// Rows [first, first + values.size() / max(cols, 1)); indices travel as doubles (exact).
    void write(std::size_t first, const std::vector<double>& values);

  private:
    std::unique_ptr<io::h5::RowWriter> writer_;
    bool indices_;
  };
  Rows write_rows(const std::string& name, std::size_t rows, std::size_t cols, bool indices) const;

  /// A text attribute of the group (a part's name).
  void write_text(const std::string& key, const std::string& text);
  /// InputError unless the attribute holds `text`.
  void expect_text(const std::string& key, const std::string& text) const;

  double read_double(const std::string& name) const;
  std::int64_t read_int64(const std::string& name) const;
  /// Arrays of any length.
  std::vector<double> read_doubles(const std::string& name) const;
  std::vector<std::uint32_t> read_uint32s(const std::string& name) const;
  /// Into an array of the run's own length: InputError if the stored one differs.
  void read_into(const std::string& name, std::vector<double>& values) const;
  void read_into(const std::string& name, std::vector<Vec3>& values) const;

  /// Rows read at once by the piecewise reads below (256 Ki: 6 MB of vectors).
  static constexpr std::size_t kPieceRows = std::size_t(1) << 18;
  /// Rows [first, first + count) of index array `name` (InputError past its end, or for a value
  /// that is not an index), and `rows` its length: an array read a piece at a time.
  std::vector<std::uint32_t> read_uint32s(const std::string& name, std::size_t first, std::size_t count,
                                          std::size_t* rows = nullptr) const;
  /// The same rows as stored, unchecked: for a reader that finds the first bad value itself (the
  /// ranks of a restart agree on it). is_index is read_uint32s's test, not_an_index its error
  /// for `value` in array `name`.
  std::vector<std::int64_t> read_int64s(const std::string& name, std::size_t first, std::size_t count,
                                        std::size_t* rows = nullptr) const;
  static bool is_index(std::int64_t value) { return value >= 0 && value <= std::int64_t(UINT32_MAX); }
  InputError not_an_index(const std::string& name, std::int64_t value) const;
  /// The rows at the ascending indices `at` of array `name`, which must have `rows` rows
  /// (InputError otherwise), read a piece at a time: a rank of a distributed restart holds its
  /// part of an array, never the whole array (SphereSystem::read_slots and load_state).
  std::vector<double> read_at(const std::string& name, std::size_t rows, const std::vector<std::uint32_t>& at) const;
  std::vector<Vec3> read_vec3s_at(const std::string& name, std::size_t rows, const std::vector<std::uint32_t>& at) const;
  std::vector<std::uint32_t> read_uint32s_at(const std::string& name, std::size_t rows, const std::vector<std::uint32_t>& at) const;

  /// "FILE:/model/kernel", for messages.
  const std::string& where() const { return where_; }
  std::int64_t id() const { return id_; }

private:
  std::int64_t id_;
  std::string where_;
};

}  // namespace mesowave::dem
