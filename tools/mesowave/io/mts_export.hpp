#pragma once
// Text exports of MTS 793 testing-machine software (TestSuite/MPT), as
// laboratories hand them over - read as they are:
//
//   MTS793|MPT|DEU|1|2|,|.|:|49|1|1|A         <- signature; 6th field: decimal separator
//   (blank)
//   Bediener Information ... Zeit: ...        <- operator header: "Key :<TAB>value" lines
//   Durchmesser :<TAB>98,6
//   Bediener Information Ende
//   (blank)
//   Datenerfassung<TAB>...<TAB>Zeit:<TAB>387,07<TAB>s<TAB>01.09.2014 14:36:18   <- a data block
//   Datum<TAB>Laufzeit<TAB>Ch 1 Kraft ...     <- column names
//   d<TAB>s<TAB>kN ...                         <- units
//   41883<TAB>16,648438<TAB>-1 ...             <- rows, decimal commas, tabs; empty field = no reading
//
// Files are Latin-1 (ISO-8859-1); text is converted to UTF-8 ("Länge").
// A file may hold several blocks: the time series (sometimes split over
// several blocks with the same columns) and short peak/valley summaries.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mesowave::io {

struct MtsBlock {
  std::vector<std::string> names;
  std::vector<std::string> units;
  std::vector<std::vector<double>> columns;  ///< one per name; NaN for an empty field
  std::size_t first_line = 0;                ///< 1-based line of the names row
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
  std::optional<std::size_t> find(std::string_view name) const;
};

struct MtsExport {
  std::string origin;
  char decimal_separator = ',';
  std::vector<std::pair<std::string, std::string>> header;  ///< operator header, key without ':' and unit suffix
  std::vector<MtsBlock> blocks;

  /// First header value whose key starts with `key` ("Durchmesser" matches
  /// "Durchmesser [mm]"), as a number; nullopt if absent or not a number.
  std::optional<double> header_number(std::string_view key) const;
  std::optional<std::string> header_text(std::string_view key) const;
};

/// True if the file starts with the MTS793 signature.
bool is_mts_export(const std::filesystem::path& path);

/// InputError naming file and line for anything malformed.
MtsExport read_mts_export(const std::filesystem::path& path);
MtsExport parse_mts_export(std::string_view latin1_text, std::string origin);

/// ISO-8859-1 bytes to UTF-8.
std::string latin1_to_utf8(std::string_view text);

}  // namespace mesowave::io
