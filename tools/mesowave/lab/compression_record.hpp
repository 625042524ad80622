#pragma once
// A load-frame record of a compression test, read from what the machine
// exported: time, force (or stress), crosshead (stroke) and extensometer
// displacements, in SI, compression positive.
//
// Formats (docs/formats.md, "Lab raw data"):
//  - csv:    comma-separated, one header row whose names carry their unit after
//            the last '_' (t_s, force_kN, stress_MPa, crosshead_mm, ext1_mm, ...);
//            an empty extensometer field means "no reading".
//  - mts793: MTS 793 text export as is (Latin-1, tabs, decimal commas, several
//            data blocks; io/mts_export.hpp). Default columns: Laufzeit, Ch 1 Kraft,
//            Ch 1 Weg and every other column in mm not named "Ch ..." as an
//            extensometer; blocks of at most two rows (peak/valley summaries)
//            are skipped, time-series blocks with the same columns are joined.
//
// Signs: machines record compression as negative force and shortening as
// negative displacement, or not. The force is turned positive in compression
// (by the sign of its largest magnitude) and every displacement channel is
// turned to rise with the force (by a vote of the signs of their increments on
// the load ramps, which offsets and zeroing jumps cannot sway); each flip is
// reported in `notes`.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mesowave::lab {

enum class RecordFormat { automatic, csv, mts793 };

/// Column names; empty = the format's default.
struct ColumnSelection {
  std::string time, force, stress, crosshead;
  std::vector<std::string> extensometers;
  bool no_crosshead = false;
};

struct CompressionRecord {
  std::string origin;
  std::string format;                      ///< "csv" or "mts793"
  std::vector<double> t_s;
  std::vector<double> force_N;             ///< empty if the file gives stress
  std::vector<double> stress_Pa;           ///< from the file, or force / area (set_loaded_area)
  std::vector<std::string> extensometer_names;
  std::vector<std::vector<double>> extensometer_m;  ///< NaN = no reading
  std::string crosshead_name;
  std::vector<double> crosshead_m;         ///< empty if none
  std::optional<double> header_diameter_m; ///< MTS header "Durchmesser"
  std::optional<double> header_length_m;   ///< MTS header "Länge" or "Höhe"
  std::vector<std::string> notes;          ///< what the reader did (sign flips, skipped blocks)
};

/// Reads and checks a record: time strictly increasing (InputError naming the
/// row otherwise), time and force/stress present in every row.
CompressionRecord read_compression_record(const std::filesystem::path& path, RecordFormat format,
                                          const ColumnSelection& columns);

/// stress = force / area.
void set_loaded_area(CompressionRecord& record, double area_m2);

/// Unit factor to SI of a unit text ("kN" -> 1e3, "mm" -> 1e-3, "s", "MPa");
/// `kind` is time, force, stress or length. InputError for anything else.
double unit_to_si(const std::string& unit, const std::string& kind, const std::string& where);

}  // namespace mesowave::lab
