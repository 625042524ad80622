#pragma once
// Outputs appear whole or not at all: every file a run writes goes to a
// temporary sibling first and is renamed into place only when the whole run
// has succeeded, so an error or an interrupt never leaves half a file behind.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mesowave::io {

class OutputStage {
public:
  OutputStage() = default;
  OutputStage(const OutputStage&) = delete;
  OutputStage& operator=(const OutputStage&) = delete;
  ~OutputStage();

  /// Reserves `final_path` and returns the temporary path to write it to (in
  /// the same directory, so the final rename is atomic). Creates missing parent
  /// directories. Staging the same path twice is an InputError.
  std::filesystem::path stage(const std::filesystem::path& final_path);

  /// Stages `final_path` and writes `content` to it.
  void write_text(const std::filesystem::path& final_path, std::string_view content);

  /// Renames every staged file into place; returns the final paths in the
  /// order they were staged. A staged file that was never written is an error.
  std::vector<std::filesystem::path> commit();

  /// Removes every staged temporary (called by the destructor if not committed).
  void discard();

  const std::vector<std::filesystem::path>& final_paths() const { return finals_; }
  /// Where each staged file is being written until commit().
  const std::vector<std::filesystem::path>& temp_paths() const { return temps_; }

private:
  std::vector<std::filesystem::path> finals_;
  std::vector<std::filesystem::path> temps_;
};

}  // namespace mesowave::io
