#include "mesowave/report/report_spec.hpp"

#include <toml++/toml.h>

#include "mesowave/core/error.hpp"

namespace mesowave::report {

ReportSpec read_report_spec(const std::filesystem::path& path) {
  toml::table root;
  try {
    root = toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(path.string() + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  ReportSpec spec;
  spec.title = root["title"].value_or(std::string("mesowave report"));
  spec.text = root["text"].value_or(std::string());
  const toml::array* sections = root["section"].as_array();
  if (!sections || sections->empty()) throw InputError(path.string() + ": no [[section]]");
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

}  // namespace mesowave::report
