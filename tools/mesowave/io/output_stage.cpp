#include "mesowave/io/output_stage.hpp"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <system_error>

#include "mesowave/core/error.hpp"

namespace mesowave::io {
namespace fs = std::filesystem;

OutputStage::~OutputStage() { discard(); }

fs::path OutputStage::stage(const fs::path& final_path) {
  const fs::path target = fs::absolute(final_path).lexically_normal();
  if (std::find(finals_.begin(), finals_.end(), target) != finals_.end())
    throw InputError("output " + final_path.string() + " is named twice");
  if (target.filename().empty()) throw InputError("output path " + final_path.string() + " names a directory");
  std::error_code ec;
  fs::create_directories(target.parent_path(), ec);
  if (ec) throw InputError("cannot create directory " + target.parent_path().string() + ": " + ec.message());
  if (fs::is_directory(target)) throw InputError("output " + final_path.string() + " is a directory");
  fs::path temp = target.parent_path() /
                  ("." + target.filename().string() + ".part-" + std::to_string(::getpid()));
  finals_.push_back(target);
  temps_.push_back(temp);
  return temp;
}

void OutputStage::write_text(const fs::path& final_path, std::string_view content) {
  const fs::path temp = stage(final_path);
  std::ofstream out(temp, std::ios::binary);
  out.write(content.data(), std::streamsize(content.size()));
  out.close();
  if (!out) throw InputError("cannot write " + final_path.string());
}

std::vector<fs::path> OutputStage::commit() {
  for (std::size_t i = 0; i < temps_.size(); ++i)
    if (!fs::exists(temps_[i]))
      throw std::runtime_error("output " + finals_[i].string() + " was staged but never written");
  for (std::size_t i = 0; i < temps_.size(); ++i) {
    std::error_code ec;
    fs::rename(temps_[i], finals_[i], ec);
    if (ec) throw InputError("cannot move output into place at " + finals_[i].string() + ": " + ec.message());
  }
  temps_.clear();
  return finals_;
}

void OutputStage::discard() {
  for (const auto& temp : temps_) {
    std::error_code ignored;
    fs::remove(temp, ignored);
  }
  temps_.clear();
}

}  // namespace mesowave::io
