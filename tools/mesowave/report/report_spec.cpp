#include "mesowave/report/report_spec.hpp"

#include <toml++/toml.h>

#include "mesowave/core/error.hpp"

namespace mesowave::report {

namespace {

// One file's title, text and sections. `first`: the file that may give the title and the text,
// and that must hold a [[section]] when it is the only one (`alone`).
ReportSpec read_one(const std::filesystem::path& path, bool first, bool alone, const std::filesystem::path& first_path) {
  toml::table root;
  try {
    root = toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(path.string() + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  if (!first && (root.contains("title") || root.contains("text")))
    throw InputError(path.string() + ": title and text belong in the first spec (" + first_path.string() +
                     "); a further spec only adds [[section]]s");
  ReportSpec spec;
  spec.title = root["title"].value_or(std::string("mesowave report"));
  spec.text = root["text"].value_or(std::string());
  const toml::array* sections = root["section"].as_array();
  if (!sections || sections->empty()) {
    if (alone) throw InputError(path.string() + ": no [[section]]");
    return spec;
  }
  for (std::size_t s = 0; s < sections->size(); ++s) {
    const toml::table* table = sections->get(s)->as_table();
    const std::string where = path.string() + ": section " + std::to_string(s + 1);
    if (!table) throw InputError(where + " is not a table");
    ReportSection section;
    section.title = (*table)["title"].value_or(std::string());
    if (section.title.empty()) throw InputError(where + " has no title");
    section.text = (*table)["text"].value_or(std::string());
    if (const toml::array* items = (*table)["item"].as_array()) {
      for (std::size_t i = 0; i < items->size(); ++i) {
        const toml::table* item = items->get(i)->as_table();
        const std::string at = where + " ('" + section.title + "'), item " + std::to_string(i + 1);
        if (!item) throw InputError(at + " is not a table");
        ReportItem r;
        int kinds = 0;
        if (auto f = (*item)["table"].value<std::string>()) r.kind = ReportItem::Kind::Table, r.file = *f, ++kinds;
        if (auto f = (*item)["figure"].value<std::string>()) r.kind = ReportItem::Kind::Figure, r.file = *f, ++kinds;
        if (auto f = (*item)["note"].value<std::string>()) r.kind = ReportItem::Kind::Note, r.file = *f, ++kinds;
        if (kinds != 1) throw InputError(at + " must name exactly one of table, figure, note");
        r.caption = (*item)["caption"].value_or(std::string());
        section.items.push_back(std::move(r));
      }
    }
    spec.sections.push_back(std::move(section));
  }
  return spec;
}

}  // namespace

ReportSpec read_report_spec(const std::filesystem::path& path) { return read_one(path, true, true, path); }

ReportSpec read_report_spec(const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) throw InputError("no report spec given");
  ReportSpec spec = read_one(paths.front(), true, paths.size() == 1, paths.front());
  for (std::size_t f = 1; f < paths.size(); ++f) {
    ReportSpec part = read_one(paths[f], false, false, paths.front());
    for (auto& section : part.sections) spec.sections.push_back(std::move(section));
  }
  if (spec.sections.empty()) throw InputError(paths.front().string() + " and the specs after it hold no [[section]]");
  return spec;
}

}  // namespace mesowave::report
