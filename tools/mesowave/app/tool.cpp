#include "mesowave/app/tool.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>

#include "mesowave/app/interrupt.hpp"
#include "mesowave/app/process_info.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/core/version.hpp"
#include "mesowave/io/quantity_file.hpp"
#include "mesowave/prov/database.hpp"
#include "mesowave/prov/run_status.hpp"

namespace mesowave::app {
namespace fs = std::filesystem;

namespace {

// CLI11 reads `--from` files through this: every quantity becomes the value of
// the option it names, on the tool and on the subcommand the command line chose
// (`mw-dem run --from calibration.json` fills run's --E-dem-GPa). CLI11 ignores
// entries no option takes; check_from_contract() then makes them errors unless
// the file declared them foreign. CLI11 reads the files after the command line,
// so the chosen subcommand is known.
class QuantityConfig : public CLI::Config {
public:
  explicit QuantityConfig(const CLI::App* root) : root_(root) {}
  std::string to_config(const CLI::App*, bool, bool, std::string) const override { return {}; }
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override {
    std::ostringstream text;
    text << input.rdbuf();
    std::vector<std::vector<std::string>> paths = {{}};
    for (const CLI::App* app = root_; app;) {
      const auto chosen = app->get_subcommands();
      if (chosen.empty()) break;
      app = chosen.front();
      paths.push_back(paths.back());
      paths.back().push_back(app->get_name());
    }
    std::vector<CLI::ConfigItem> items;
    for (const auto& q : io::parse_quantity_text(text.str(), "--from file"))
      for (const auto& parents : paths) {
        CLI::ConfigItem item;
        item.parents = parents;
        item.name = q.option_name();
        item.inputs = {q.value};
        items.push_back(std::move(item));
      }
    return items;
  }

private:
  const CLI::App* root_;
};

// The tool and the subcommands the command line chose, outermost first: the
// options a --from entry may fill.
std::vector<const CLI::App*> chosen_apps(const CLI::App& root) {
  std::vector<const CLI::App*> apps = {&root};
  while (!apps.back()->get_subcommands().empty()) apps.push_back(apps.back()->get_subcommands().front());
  return apps;
}

// Whether an entry named `option` fills an option, by CLI11's own lookup for
// config items (App::_parse_single_config: "--name", "-n", then "name").
bool takes(const std::vector<const CLI::App*>& apps, const std::string& option) {
  return std::any_of(apps.begin(), apps.end(), [&](const CLI::App* app) {
    return app->get_option_no_throw("--" + option) ||
           (option.size() == 1 && app->get_option_no_throw("-" + option)) || app->get_option_no_throw(option);
  });
}

// The --from contract: every entry of a --from file fills an option of the tool
// (or of the chosen subcommand), or its file declared it foreign, or the command
// line's --from-ignore names it; anything else is a renamed or misplaced value
// that would silently leave an option at its default. Returns the entries left
// untaken, by file, for the run record.
nlohmann::ordered_json check_from_contract(const CLI::App& root,
                                           const std::vector<std::pair<std::string, io::QuantityFile>>& files,
                                           const std::vector<std::string>& consumer_ignores) {
  auto listed = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  for (const auto& name : consumer_ignores)
    if (std::none_of(files.begin(), files.end(), [&](const auto& file) {
          return std::any_of(file.second.quantities.begin(), file.second.quantities.end(),
                             [&](const io::Quantity& q) { return q.name == name; });
        }))
      throw InputError("--from-ignore names '" + name + "', which is an entry of no --from file");
  const auto apps = chosen_apps(root);
  std::string tool = root.get_name();
  for (std::size_t i = 1; i < apps.size(); ++i) tool += " " + apps[i]->get_name();
  nlohmann::ordered_json ignored = nlohmann::ordered_json::object();
  for (const auto& [path, file] : files) {
    std::vector<const io::Quantity*> stray;
    for (const auto& q : file.quantities) {
      if (takes(apps, q.option_name())) continue;
      if (!listed(file.foreign_keys, q.name) && !listed(consumer_ignores, q.name))
        stray.push_back(&q);
      else
        ignored[path].push_back(q.name);
    }
    if (stray.empty()) continue;
    std::string names;
    for (const auto* q : stray) names += (names.empty() ? "'" : ", '") + q->name + "' (--" + q->option_name() + ")";
    throw InputError("--from " + path + ": " + (stray.size() == 1 ? "entry " : "entries ") + names + " fill" +
                     (stray.size() == 1 ? "s" : "") + " no option of " + tool + " (a value meant for another reader: " +
                     "list it in the file's " + io::kForeignKeys + " or in --from-ignore)");
  }
  return ignored;
}

// `--from` files, found before CLI11 parses so that a bad file is reported by
// name (CLI11 hands the reader only a stream).
std::vector<std::string> from_files_in(int argc, char** argv) {
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg == "--from" && i + 1 < argc) files.emplace_back(argv[++i]);
    else if (arg.rfind("--from=", 0) == 0) files.push_back(arg.substr(7));
  }
  return files;
}

// The arguments for CLI11 (program name dropped), with every `--from FILE`
// moved to the front: CLI11 2.1 applies a config option given after a
// subcommand only to options that are not required, so `mw-calibrate cube
// --from static-test.toml` would miss its required targets. Anywhere on the
// line, --from means the same.
std::vector<std::string> from_options_first(int argc, char** argv) {
  std::vector<std::string> from, rest;
  bool literal = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (!literal && arg == "--") literal = true;
    if (!literal && arg == "--from" && i + 1 < argc) {
      from.insert(from.end(), {arg, argv[++i]});
    } else if (!literal && arg.rfind("--from=", 0) == 0) {
      from.push_back(arg);
    } else {
      rest.push_back(arg);
    }
  }
  from.insert(from.end(), rest.begin(), rest.end());
  std::reverse(from.begin(), from.end());  // CLI11 takes a vector in reverse order
  return from;
}

nlohmann::ordered_json json_value(const std::string& text) {
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (!text.empty() && end == text.c_str() + text.size()) return number;
  if (text == "true") return true;
  if (text == "false") return false;
  return text;
}

// Every option's final value, whether typed, read from a --from file or
// defaulted, keyed by its long name; subcommands nest.
nlohmann::ordered_json collect_params(const CLI::App& app) {
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const CLI::Option* opt : app.get_options()) {
    const std::string name = opt->get_lnames().empty() ? opt->get_name() : opt->get_lnames().front();
    if (name == "help" || name == "help-all" || name == "version" || name == "db") continue;
    const auto& results = opt->results();
    if (!results.empty()) {
      if (results.size() == 1) params[name] = json_value(results.front());
      else {
        auto list = nlohmann::ordered_json::array();
        for (const auto& r : results) list.push_back(json_value(r));
        params[name] = list;
      }
    } else if (!opt->get_default_str().empty()) {
      params[name] = json_value(opt->get_default_str());
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) {
    params["subcommand"] = sub->get_name();
    params[sub->get_name()] = collect_params(*sub);
  }
  return params;
}

std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

}  // namespace

// ---- Run --------------------------------------------------------------------

void Run::input(const fs::path& path) {
  if (!fs::is_regular_file(path)) throw InputError("input " + path.string() + " does not exist or is not a file");
  inputs_.push_back(prov::describe_file(path));
}

fs::path Run::output(const fs::path& path) { return stage_.stage(path); }

void Run::write_text(const fs::path& path, std::string_view content) { stage_.write_text(path, content); }

void Run::metric(const std::string& name, double value, const std::string& unit) {
  metrics_.push_back({name, value, unit});
}

void Run::param(const std::string& name, nlohmann::ordered_json value) { extra_params_[name] = std::move(value); }

void Run::keep_on_interrupt(const std::filesystem::path& path, const std::string& what) {
  const std::string entry = path.string() + " (" + what + ")";
  const auto same_file = [&](const std::string& k) { return k.rfind(path.string() + " (", 0) == 0; };
  const auto it = std::find_if(kept_.begin(), kept_.end(), same_file);
  if (it != kept_.end()) *it = entry;
  else kept_.push_back(entry);
}

nlohmann::ordered_json Run::origin(const std::string& option) const {
  nlohmann::ordered_json o = {{"option", option}};
  for (const auto& arg : command_line_) {
    if (arg == "--") break;
    if (arg == option || arg.rfind(option + "=", 0) == 0) {
      o["given"] = "command line";
      return o;
    }
  }
  const std::string name = option.rfind("--", 0) == 0 ? option.substr(2) : option;
  for (auto file = from_files_.rbegin(); file != from_files_.rend(); ++file)  // the last file named wins
    for (const auto& q : file->content.quantities)
      if (q.option_name() == name) {
        o.update({{"file", file->path}, {"entry", q.name}, {"sha256", file->sha256}, {"source", q.source}});
        if (q.source != "output") o["cite"] = q.cite;  // a tool's JSON: its cite is only the file's name
        return o;
      }
  o["given"] = "default";
  return o;
}

void Run::emit_json(const nlohmann::ordered_json& object, const fs::path& out_path) {
  const std::string text = object.dump(2) + "\n";
  std::cout << text;
  if (!out_path.empty()) write_text(out_path, text);
}

std::ostream& Run::out() { return std::cout; }

// ---- Tool -------------------------------------------------------------------

Tool::Tool(std::string name, std::string description) : name_(std::move(name)), app_(description, name_) {
  app_.set_version_flag("--version", name_ + " " + source_version());
  app_.config_formatter(std::make_shared<QuantityConfig>(&app_));
  app_.allow_config_extras(CLI::config_extras_mode::ignore_all);
  app_.fallthrough();  // --db, --from and --json may follow a subcommand
  app_.set_config("--from", "",
                  "Read option values from FILE: lab-data TOML ([t_p] value = 35, unit = \"us\" fills --t-p-us) "
                  "or an earlier tool's JSON ({\"E_d_GPa\": 36.7} fills --E-d-GPa). Repeatable; the last file wins, "
                  "the command line beats them all.")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("FILE");
  app_.add_option("--from-ignore", from_ignore_,
                  "Entries of the --from files this run may leave untaken (KEY[,KEY...], repeatable; recorded as "
                  "from_ignored): every other entry must fill an option, or be declared in its file's foreign_keys")
      ->delimiter(',')
      ->configurable(false)
      ->type_name("KEY");
  app_.add_option("--db", db_path_,
                  "Record this run in the provenance database PATH (SQLite; created if absent)")
      ->envname("MESOWAVE_DB")
      ->type_name("PATH");
  app_.get_formatter()->column_width(34);
}

int Tool::run(int argc, char** argv, const std::function<void(Run&)>& body) {
  const auto wall_start = std::chrono::steady_clock::now();
  prov::RunRecord record;
  record.tool = name_;
  record.started_at = utc_timestamp();
  record.argv.assign(argv, argv + argc);

  nlohmann::ordered_json from_ignored;
  std::vector<std::pair<std::string, io::QuantityFile>> from_files;
  try {
    for (const auto& file : from_files_in(argc, argv))  // named errors first
      from_files.emplace_back(file, io::read_quantity_document(file));
    app_.parse(from_options_first(argc, argv));
    from_ignored = check_from_contract(app_, from_files, from_ignore_);
  } catch (const CLI::Success& e) {
    return app_.exit(e);
  } catch (const CLI::ParseError& e) {
    report_error(one_line(e.what()) + " (see " + name_ + " --help)", 1);
    return 1;
  } catch (const InputError& e) {
    report_error(one_line(e.what()), 1);
    return 1;
  }

  std::optional<prov::Database> db;
  Run run;
  if (!from_ignored.empty()) run.param("from_ignored", from_ignored);
  try {
    if (records_runs_ && !db_path_.empty()) db.emplace(prov::Database::open(db_path_));
    for (const auto& file : app_.get_option("--from")->as<std::vector<std::string>>())
      if (!file.empty()) run.input(file);
    for (auto& [path, content] : from_files)
      run.from_files_.push_back({path, std::move(content), prov::describe_file(path).sha256});
    for (int i = 1; i < argc; ++i) {  // the command line without its --from files, for Run::origin
      const std::string arg = argv[i];
      if (arg == "--from") ++i;
      else if (arg.rfind("--from=", 0) != 0) run.command_line_.push_back(arg);
    }
  } catch (const InputError& e) {
    report_error(one_line(e.what()), 1);
    return 1;
  }

  // From here on a SIGINT or SIGTERM stops the body at its next Progress::update (or is seen
  // when the body returns) and the run is recorded as interrupted (app/interrupt.hpp).
  InterruptGuard interrupt_guard;
  std::optional<Interrupted> interrupted;
  try {
    body(run);
  } catch (const Interrupted& i) {
    interrupted = i;
  } catch (const InputError& e) {
    record.exit_status = 1;
    record.error = one_line(e.what());
  } catch (const CLI::Error& e) {
    record.exit_status = 1;
    record.error = one_line(e.what());
  } catch (const std::exception& e) {
    record.exit_status = 2;
    record.error = "internal error: " + one_line(e.what());
  }
  if (!interrupted && interrupt_signal()) interrupted = Interrupted{interrupt_signal(), last_progress()};

  record.params = collect_params(app_);
  for (auto& [key, value] : run.extra_params_.items()) record.params[key] = value;
  if (interrupted) {
    record.exit_status = prov::interrupted_exit_status(interrupted->signal);
    record.error = "interrupted by " + signal_name(interrupted->signal);
    nlohmann::ordered_json where = {{"signal", signal_name(interrupted->signal)}};
    if (const auto& m = interrupted->reached) {
      record.error += " after " + std::to_string(m->done) + " of " + std::to_string(m->total) + " " + m->unit + " (" +
                      m->label + ")";
      where.update({{"label", m->label}, {"done", m->done}, {"total", m->total}, {"unit", m->unit}});
    }
    record.error += "; no output was written";
    for (const auto& kept : run.kept_) record.error += "; kept " + kept;
    record.params["interrupted"] = where;
  }
  record.inputs = run.inputs_;
  record.metrics = run.metrics_;
  // The thread count earns the wall time (the bits do not depend on it): recorded for every run that chose it.
  const auto named = [&record](const char* name) {
    return std::any_of(record.metrics.begin(), record.metrics.end(), [name](const auto& m) { return m.name == name; });
  };
  if (const auto t = threads_chosen(); t && !named("threads")) record.metrics.push_back({"threads", double(t->count), ""});
  try {
    if (record.exit_status == 0)
      for (std::size_t i = 0; i < run.stage_.final_paths().size(); ++i)
        record.outputs.push_back(prov::describe_file(run.stage_.final_paths()[i], run.stage_.temp_paths()[i]));
  } catch (const std::exception& e) {
    record.exit_status = 2;
    record.error = "internal error: " + one_line(e.what());
  }

  if (!db && record.exit_status != 0 && failure_gate_ && !db_path_.empty() && failure_gate_()) {
    try {
      db.emplace(prov::Database::open(db_path_));
    } catch (const std::exception&) {  // the failure itself is still reported below
    }
  }
  if (db) {
    const auto usage = resource_usage();
    record.version = source_version();
    record.binary_sha256 = executable_sha256();
    record.cwd = fs::current_path().string();
    record.host = host_name();
    record.ended_at = utc_timestamp();
    record.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    record.cpu_s = usage.cpu_s;
    record.peak_rss_kib = usage.peak_rss_kib;
    try {
      prov::record_run(*db, record);
    } catch (const std::exception& e) {
      record.exit_status = 2;
      record.error = "cannot record the run in " + db_path_ + ": " + one_line(e.what());
    }
  }

  if (record.exit_status == 0) {
    try {
      run.stage_.commit();
    } catch (const std::exception& e) {
      record.exit_status = 2;
      record.error = one_line(e.what());
    }
  } else {
    run.stage_.discard();
  }
  if (record.exit_status != 0) report_error(record.error, record.exit_status);
  return record.exit_status;
}

void Tool::report_error(const std::string& line, int status) const {
  if (error_report_) error_report_(line, status);
  else std::cerr << "error: " << line << "\n";
}

void declare_products(nlohmann::ordered_json& object, const std::vector<std::string>& products) {
  for (const auto& p : products)
    if (!object.contains(p)) throw std::logic_error("declare_products: '" + p + "' is not an entry of the result");
  nlohmann::ordered_json foreign = nlohmann::ordered_json::array();
  for (const auto& [key, value] : object.items())
    if (key != "foreign_keys" && std::find(products.begin(), products.end(), key) == products.end()) foreign.push_back(key);
  object["foreign_keys"] = foreign;
}

CLI::Option* add_out_option(CLI::App& app, fs::path& out, const std::string& what) {
  return app.add_option("--out", out, "Also write " + what + " to FILE")->type_name("FILE");
}

}  // namespace mesowave::app
