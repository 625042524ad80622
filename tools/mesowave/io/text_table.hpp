#pragma once
// Aligned plain-text tables for terminals (numbers right-aligned, text left).
#include <string>
#include <vector>

namespace mesowave::io {

std::string format_text_table(const std::vector<std::string>& header,
                              const std::vector<std::vector<std::string>>& rows);

}  // namespace mesowave::io
