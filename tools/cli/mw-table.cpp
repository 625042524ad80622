// mw-table - summary tables and their plots from other runs' outputs, as recorded runs: the
// concrete paper's Table 3 gathered from one mw-pcc table per frequency, a speed-against-error
// table from the DEM run summaries, a gnuplot figure of any tables, a table as Markdown, and the
// rod paper's findings checked on the rod's tables - so every number and figure of the report
// has a provenance run whose inputs are the files it came from. Examples: --help.
#include "mesowave/app/tool.hpp"
#include "mesowave/io/table_gather.hpp"
#include "mesowave/io/text_table.hpp"
#include "mesowave/io/table_plot.hpp"
#include "mesowave/wave/rod_findings.hpp"

using namespace mesowave;
namespace fs = std::filesystem;
using Style = io::ColumnFormat::Style;

int main(int argc, char** argv) {
  app::Tool tool("mw-table",
                 "Tables made of other runs' outputs, and plots of tables. gather: one row per --row KEY=FILE[,FILE...], "
                 "each --column NAME=SOURCE taken from the first of the row's files that holds SOURCE - a CSV column "
                 "(in the row --where COLUMN=VALUE, or NAME=SOURCE@COLUMN=VALUE, picks), a JSON key (a.b for nested "
                 "objects) or a lab-data TOML entry; --join adds columns of a keyed table (e.g. the paper's). plot: "
                 "columns of a CSV table against one, through gnuplot, one series per --y (or one point per row with "
                 "--label-column). Every file read is an input of the run.\n\n"
                 "  mw-table gather --key-name f_kHz --row 100=pcc-100kHz.csv --row 150=pcc-150kHz.csv --where "
                 "sensor=mean --column pcc_mean=pcc_signal --join lab-data/concrete-cube/paper/table3.csv:paper=pcc_mean "
                 "--csv table3.csv\n"
                 "  mw-table gather --key-name run --row full=dem-full.json --column wall_s --column "
                 "residual=energy.residual_relative --csv speed.csv\n"
                 "  mw-table plot table3.csv --x f_kHz --y pcc_mean=mesowave --y paper --out table3.png\n"
                 "  mw-table plot speed.csv --x wall_s --y error --label-column run --log-x --log-y --out speed.png");
  auto& cli = tool.cli();
  cli.require_subcommand(1);

  auto* gather = cli.add_subcommand("gather", "One row per run: values picked from the runs' CSV, JSON or TOML files");
  std::string key_name = "key", where_text, fem_column;
  int significant_digits = 0;
  std::vector<std::string> row_texts, column_texts, join_texts, pareto;
  fs::path csv_out;
  gather->add_option("--key-name", key_name, "Header of the key column (e.g. f_kHz; A,B: two, and rows A_VALUE,B_VALUE=FILE)")->capture_default_str();
  gather->add_option("--row", row_texts, "KEY=FILE[,FILE...]: one row; repeatable, in order")->required();
  gather->add_option("--column", column_texts,
                     "NAME[=SOURCE][@COLUMN=VALUE]: an output column from a CSV column or JSON/TOML key (SOURCE may be A|B: A in any of the row's files, else B, for a quantity named differently in different files; mean(S) or median(S): over all the row's files; a VALUE {K}: the row's key K); repeatable")
      ->required();
  gather->add_option("--where", where_text, "COLUMN=VALUE: the row of every CSV file to take values from");
  gather->add_option("--join", join_texts,
                     "FILE:NAME=SOURCE[,NAME=SOURCE...]: columns of a CSV table with the key column, matched by key "
                     "(empty where it has no row); repeatable");
  gather->add_option("--csv", csv_out, "The table to write (CSV)")->type_name("FILE")->required();
  gather->add_option("--significant-digits", significant_digits,
                     "Round the numbers taken from JSON files to this many significant digits (default: all, "
                     "the shortest text that reads back exactly; CSV and TOML values are copied as written)")
      ->check(CLI::Range(1, 17));
  std::vector<std::string> decimals_texts, round_texts, join_as_texts, header_texts, md_decimals, md_significant;
  gather->add_option("--decimals", decimals_texts, "NAME=N: print column NAME with N decimals (0.150); repeatable");
  gather->add_option("--round", round_texts, "NAME=N: round column NAME to N decimals, shortest text (0.15); repeatable");
  gather->add_option("--join-as", join_as_texts, "KEY=KEY: a row key as the --join tables spell it; repeatable");
  gather->add_option("--pareto", pareto, "min:COLUMN,max:COLUMN: a last column 'pareto', yes on the rows no other row beats in both (e.g. min:wall_s,max:pcc)")->delimiter(',')->expected(2);

  auto* markdown = cli.add_subcommand("markdown", "A CSV table as a Markdown table");
  io::MarkdownTableOptions mo;
  fs::path markdown_table, markdown_out;
  markdown->add_option("table", markdown_table, "CSV table")->required();
  markdown->add_option("--header", header_texts, "COLUMN=TEXT: the column's header; repeatable");
  markdown->add_option("--decimals", md_decimals, "COLUMN=N: its numbers with N decimals; repeatable");
  markdown->add_option("--significant", md_significant, "COLUMN=N: its numbers with N significant digits; repeatable");
  markdown->add_option("--empty", mo.empty, "What an empty field shows")->capture_default_str();
  markdown->add_option("--out", markdown_out, "Markdown file to write")->type_name("FILE")->required();

  auto* findings = cli.add_subcommand("findings", "The rod paper's findings checked on the rod study's tables");
  fs::path velocity_table, table1, table2, findings_out;
  findings->add_option("--velocity", velocity_table, "Group velocity: f_kHz, then a column per model")->required();
  findings->add_option("--table1", table1, "Rod Table 1: model, pcc_vs_fem_envelope")->required();
  findings->add_option("--table2", table2, "Rod Table 2: model, rss_m2_s2")->required();
  findings->add_option("--fem-column", fem_column, "The FEM's column of --velocity")->required();
  findings->add_option("--out", findings_out, "Markdown check list to write")->type_name("FILE")->required();

  auto* plot = cli.add_subcommand("plot", "Columns of a CSV table against one of its columns (gnuplot)");
  fs::path table_path, plot_out;
  io::TablePlotOptions o;
  std::vector<double> y_range;
  plot->add_option("table", table_path, "CSV table")->required();
  plot->add_option("--x", o.x_column, "Column on the x axis")->required();
  plot->add_option("--y", o.y_columns, "COLUMN[=LEGEND]: a column on the y axis; repeatable")->required();
  plot->add_option("--label-column", o.label_column,
                   "One point per row, named by this column (speed against error), instead of one line per --y");
  plot->add_option("--style", o.style, "lines | points | linespoints")->capture_default_str();
  plot->add_option("--title", o.title, "Title");
  plot->add_option("--x-label", o.x_label, "x axis label (default: the column)");
  plot->add_option("--y-label", o.y_label, "y axis label (default: the first --y column)");
  plot->add_option("--y-range", y_range, "from,to of the y axis")->delimiter(',')->expected(2);
  plot->add_flag("--log-x", o.log_x, "Logarithmic x axis");
  plot->add_flag("--log-y", o.log_y, "Logarithmic y axis");
  plot->add_flag("--one-minus", o.one_minus,
                 "Plot 1 - y: e.g. the decorrelation 1 - PCC, which --log-y spreads out near PCC = 1 (a value of "
                 "exactly 1 has no place on a log axis and is left out)");
  plot->add_option("--key", o.key, "Where the legend goes (gnuplot: 'outside right top', 'below', 'inside bottom left')")
      ->capture_default_str();
  plot->add_option("--overlay", o.overlays, "FILE:COLUMN[=LEGEND]: a line from another table, against its --x column");
  plot->add_option("--out", plot_out, "Figure to write (.png or .svg)")->type_name("FILE")->required();

  return tool.run(argc, argv, [&](app::Run& run) {
    if (gather->parsed()) {
      io::GatherSpec spec;
      spec.key_name = key_name;
      spec.pareto = pareto;
      if (!where_text.empty()) spec.where = io::parse_row_selector(where_text);
      if (significant_digits > 0) spec.significant_digits = significant_digits;
      for (const auto& r : row_texts) spec.rows.push_back(io::parse_gather_row(r));
      for (const auto& c : column_texts) spec.columns.push_back(io::parse_column_source(c));
      for (const auto& j : join_texts) spec.joins.push_back(io::parse_table_join(j));
      for (const auto& d : decimals_texts) spec.formats.insert(io::parse_column_format(d, Style::fixed));
      for (const auto& d : round_texts) spec.formats.insert(io::parse_column_format(d, Style::rounded));
      for (const auto& a : join_as_texts) spec.join_keys.insert(io::parse_row_selector(a));
      for (const auto& f : spec.files()) run.input(f);
      const auto table = io::gather_rows(spec);
      run.write_text(csv_out, io::to_csv(table.header, table.rows));
      run.out() << io::format_text_table(table.header, table.rows);
      return;
    }
    if (markdown->parsed()) {
      for (const auto& h : header_texts) mo.headers.insert(io::parse_row_selector(h));
      for (const auto& d : md_decimals) mo.formats.insert(io::parse_column_format(d, Style::fixed));
      for (const auto& d : md_significant) mo.formats.insert(io::parse_column_format(d, Style::significant));
      run.input(markdown_table);
      const auto table = io::read_csv(markdown_table);
      run.write_text(markdown_out, io::format_markdown_table(table.header, table.rows, mo));
      return;
    }
    if (findings->parsed()) {
      for (const auto& f : {velocity_table, table1, table2}) run.input(f);
      const auto found = wave::rod_findings(io::read_csv(velocity_table), io::read_csv(table1), io::read_csv(table2),
                                            fem_column);
      run.write_text(findings_out, found.markdown());
      run.out() << found.markdown();
      return;
    }
    io::require_plot_extension(plot_out);
    if (!y_range.empty()) o.y_range = std::pair{y_range[0], y_range[1]};
    io::require_table_plot_options(o);
    for (const auto& f : io::table_plot_overlay_files(o)) run.input(f);
    run.input(table_path);
    const auto table = io::read_csv(table_path);
    const auto spec = io::table_plot(table, o);
    io::render_plot(spec, plot_out, run.output(plot_out));
    run.out() << "wrote " << plot_out.string() << ": " << spec.series.size() << " series, " << table.rows.size() << " rows\n";
  });
}
