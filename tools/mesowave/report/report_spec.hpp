#pragma once
// What goes into the report: a TOML file of sections, each with paragraphs,
// tables (CSV files) and figures (PNG/SVG files), in reading order.
//
//   title = "mesowave: concrete cube and steel rod"
//   [[section]]
//   title = "Concrete cube: Table 1"
//   text = "Static moduli from the dynamic one..."       # paragraphs split on blank lines
//   [[section.item]]
//   table = "results/concrete-cube/table1-vs-paper.csv"
//   caption = "Table 1 beside the paper"
//   [[section.item]]
//   figure = "results/concrete-cube/raw-compress-fig5.png"
//   caption = "Stress-strain curves (cf. paper Fig. 5)"
//   [[section.item]]
//   note = "pipeline/concrete-cube/table1-note.txt"      # a text file, shown as a paragraph
//
// A report may be read from several files: the first gives the title and the opening text,
// each further one (a study's pipeline/<study>/report.toml) adds its sections in order, so a
// new study adds its part of the report without editing a shared file.
#include <filesystem>
#include <string>
#include <vector>

namespace mesowave::report {

struct ReportItem {
  enum class Kind { Table, Figure, Note };
  Kind kind = Kind::Table;
  std::filesystem::path file;
  std::string caption;
};

struct ReportSection {
  std::string title;
  std::string text;
  std::vector<ReportItem> items;
};

struct ReportSpec {
  std::string title;
  std::string text;
  std::vector<ReportSection> sections;
};

/// InputError naming the file and entry for a malformed spec.
ReportSpec read_report_spec(const std::filesystem::path& path);

/// The first file's title and text, then every file's sections in order. InputError for a
/// later file with a title or text of its own (the report has one), or no section in any file.
ReportSpec read_report_spec(const std::vector<std::filesystem::path>& paths);

}  // namespace mesowave::report
