// mw-compress - flowchart steps 3 and 4 from the load frame's records (concrete
// paper Section 3.2, Fig. 5): the stabilized secant modulus E_st of the cyclic
// test (EN 12390-13 method B, clause 8.2), the failure stress sigma_max of the
// destructive test, and the crosshead multiplier that turns the destructive
// test's crosshead record into strain.
//
//   mw-compress --cyclic cyclic.csv --failure failure.csv --side-mm 150 --gauge-length-mm 75 --plot fig5.png
//   mw-compress --format mts793 --cyclic BA_Los_M_V-4.dat --gauge-length-mm 100
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/gnuplot.hpp"
#include "mesowave/lab/compression_report.hpp"

using namespace mesowave;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-compress",
      "Compression-test records to E_st and sigma_max (concrete paper, Section 3.2, Fig. 5).\n"
      "Cyclic test: finds the load cycles and computes the stabilized secant modulus of EN 12390-13 (clause 8.2; "
      "method B, clause 7.3.2): E_C,S = (sigma_a - sigma_b) / (eps_a,3 - eps_b,2), stresses and mean extensometer "
      "strains averaged over the last --reading-window-s of the hold at the upper stress of cycle 3 and of the hold "
      "at the lower stress before it; every cycle's secant modulus is reported too. Extensometer channels that drop "
      "out, stick or jump are left out (and said so). Crosshead multiplier m: least squares eps_ext = m "
      "(crosshead / height) + c over the cycles from --fit-from-cycle on (the paper found 1/4.5).\n"
      "Failure test: sigma_max = peak force / loaded area; with a multiplier (fitted, or --crosshead-multiplier) the "
      "crosshead record becomes a stress-strain curve.\n"
      "Input: --format csv (t_s, force_kN or stress_MPa, crosshead_mm, ext1_mm, ...) or mts793 (MTS 793 exports as "
      "they are: Latin-1, tabs, decimal commas; docs/formats.md).\n\n"
      "  mw-compress --cyclic raw/cyclic-test.csv --failure raw/failure-test.csv --side-mm 150 --gauge-length-mm 75 "
      "--plot fig5.png --out compress.json\n"
      "  mw-compress --format mts793 --cyclic BA_Los_M_V-4.dat --gauge-length-mm 100   (area from the header)\n"
      "  mw-compress --format mts793 --failure Wolf_8.2_Probe_2.dat --diameter-mm 100");
  std::filesystem::path cyclic_file, failure_file, out, cycles_file, cyclic_curve, failure_curve, plot;
  std::string format = "auto", title;
  lab::ColumnSelection columns;
  std::optional<double> side_mm, diameter_mm, area_mm2, height_mm, gauge_mm, upper_MPa, given_multiplier;
  lab::CyclicOptions options;
  double tolerance_pct = 30;
  int fit_from = 2;
  auto& cli = tool.cli();
  cli.add_option("--cyclic", cyclic_file, "Cyclic test record (time, force, extensometers, crosshead)")->type_name("FILE");
  cli.add_option("--failure", failure_file, "Test to failure record (time, force, crosshead)")->type_name("FILE");
  cli.add_option("--format", format, "Record format: auto, csv or mts793")
      ->check(CLI::IsMember({"auto", "csv", "mts793"}))->capture_default_str();
  cli.add_option("--side-mm", side_mm, "Cube side [mm]: area side^2, height side");
  cli.add_option("--diameter-mm", diameter_mm, "Cylinder diameter [mm]: area pi d^2/4");
  cli.add_option("--area-mm2", area_mm2, "Loaded area [mm2]");
  cli.add_option("--specimen-height-mm", height_mm, "Specimen height for crosshead strain [mm]");
  cli.add_option("--gauge-length-mm", gauge_mm, "Extensometer gauge length [mm] (the paper: 75)");
  cli.add_option("--upper-stress-MPa", upper_MPa, "Expected upper stress of the cycles [MPa]: checked, not used");
  cli.add_option("--cycle", options.evaluated_cycle, "Cycle whose secant is E_st (EN 12390-13: 3)")->capture_default_str();
  cli.add_option("--reading-window-s", options.reading_window_s, "Readings average the last seconds of each hold")
      ->capture_default_str();
  cli.add_option("--min-extensometers", options.min_extensometers, "Usable channels needed")->capture_default_str();
  cli.add_option("--channel-tolerance-pct", tolerance_pct, "Channel deviation from the median that drops it")
      ->capture_default_str();
  cli.add_option("--fit-from-cycle", fit_from, "Crosshead fit over the cycles from this one on")->capture_default_str();
  cli.add_option("--crosshead-multiplier", given_multiplier, "Multiplier for the failure test's crosshead (instead of "
                                                             "the fitted one)");
  cli.add_option("--time-column", columns.time, "Time column (default t_s / Laufzeit)");
  cli.add_option("--force-column", columns.force, "Force column (default force_kN / Ch 1 Kraft)");
  cli.add_option("--stress-column", columns.stress, "Stress column instead of force");
  cli.add_option("--crosshead-column", columns.crosshead, "Crosshead column (default crosshead_mm / Ch 1 Weg)");
  cli.add_option("--extensometer-columns", columns.extensometers, "Extensometer columns (default ext*, or the mm "
                                                                   "columns of an MTS export)")->delimiter(',');
  cli.add_flag("--no-crosshead", columns.no_crosshead, "Ignore the crosshead column");
  cli.add_option("--cycles-csv", cycles_file, "Per-cycle table")->type_name("FILE");
  cli.add_option("--cyclic-curve", cyclic_curve, "Cyclic test curve CSV")->type_name("FILE");
  cli.add_option("--failure-curve", failure_curve, "Failure test curve CSV")->type_name("FILE");
  cli.add_option("--plot", plot, "PNG like the paper's Fig. 5 (gnuplot)")->type_name("FILE");
  cli.add_option("--title", title, "Plot title");
  app::add_out_option(cli, out);

  return tool.run(argc, argv, [&](app::Run& run) {
    if (cyclic_file.empty() && failure_file.empty()) throw InputError("give --cyclic FILE and/or --failure FILE");
    const auto fmt = format == "csv" ? lab::RecordFormat::csv
                     : format == "mts793" ? lab::RecordFormat::mts793 : lab::RecordFormat::automatic;
    options.channel_tolerance = require_positive("--channel-tolerance-pct", tolerance_pct, "%") / 100;
    if (upper_MPa) options.expected_upper_Pa = require_positive("--upper-stress-MPa", *upper_MPa, "MPa") * units::MPa;
    lab::CompressionAnalysis a;
    if (!cyclic_file.empty()) run.input(cyclic_file), a.cyclic_record = lab::read_compression_record(cyclic_file, fmt, columns);
    if (!failure_file.empty()) run.input(failure_file), a.failure_record = lab::read_compression_record(failure_file, fmt, columns);
    const auto& header_rec = a.cyclic_record ? *a.cyclic_record : *a.failure_record;

    // Geometry: options first, then the MTS header (cylinder).
    const int given = int(side_mm.has_value()) + int(diameter_mm.has_value()) + int(area_mm2.has_value());
    if (given > 1) throw InputError("give one of --side-mm, --diameter-mm, --area-mm2");
    if (side_mm) a.area_m2 = std::pow(require_positive("--side-mm", *side_mm, "mm") * units::mm, 2);
    else if (diameter_mm) a.area_m2 = std::numbers::pi / 4 * std::pow(require_positive("--diameter-mm", *diameter_mm, "mm") * units::mm, 2);
    else if (area_mm2) a.area_m2 = require_positive("--area-mm2", *area_mm2, "mm2") * units::mm * units::mm;
    else if (header_rec.header_diameter_m) {
      a.area_m2 = std::numbers::pi / 4 * std::pow(*header_rec.header_diameter_m, 2);
      a.geometry_note = "loaded area from the file header: cylinder of diameter " +
                        format_number(*header_rec.header_diameter_m * 1e3) + " mm";
    } else if (!header_rec.force_N.empty()) {
      throw InputError("the record gives force: say the loaded area (--side-mm, --diameter-mm or --area-mm2)");
    }
    if (height_mm) a.specimen_height_m = require_positive("--specimen-height-mm", *height_mm, "mm") * units::mm;
    else if (side_mm) a.specimen_height_m = *side_mm * units::mm;
    else if (header_rec.header_length_m) a.specimen_height_m = *header_rec.header_length_m;
    for (auto* rec : {&a.cyclic_record, &a.failure_record})
      if (*rec && a.area_m2 > 0) lab::set_loaded_area(**rec, a.area_m2);

    if (a.cyclic_record) {
      if (!gauge_mm) throw InputError("the cyclic test needs --gauge-length-mm (the extensometers' base)");
      options.gauge_length_m = a.gauge_length_m = require_positive("--gauge-length-mm", *gauge_mm, "mm") * units::mm;
      a.cyclic = lab::analyse_cyclic_test(*a.cyclic_record, options);
      if (!a.cyclic_record->crosshead_m.empty() && a.specimen_height_m)
        a.fit = lab::fit_crosshead_multiplier(*a.cyclic_record, *a.cyclic, a.gauge_length_m, *a.specimen_height_m, fit_from);
      run.metric("E_st", a.cyclic->E_st_Pa / units::GPa, "GPa");
      if (a.fit) run.metric("crosshead_multiplier", a.fit->multiplier, "");
    }
    if (given_multiplier) a.multiplier = require_positive("--crosshead-multiplier", *given_multiplier), a.multiplier_source = "given";
    else if (a.fit) a.multiplier = a.fit->multiplier, a.multiplier_source = "fitted on the cyclic test";
    if (a.failure_record) {
      a.failure = lab::analyse_failure_test(*a.failure_record, a.multiplier, a.specimen_height_m);
      run.metric("sigma_max", a.failure->sigma_max_Pa / units::MPa, "MPa");
    }

    auto summary = lab::compression_summary(a);
    // What the next step takes (mw-calibrate cube --from, docs/calibration.md); the rest is the record.
    app::declare_products(summary, lab::compression_products(a));
    for (const auto& note : summary["notes"]) std::cerr << "note: " << note.get<std::string>() << "\n";
    for (const auto& warning : summary["warnings"]) std::cerr << "warning: " << warning.get<std::string>() << "\n";
    if (!cycles_file.empty() && a.cyclic) run.write_text(cycles_file, lab::cycles_csv(a));
    if (!cyclic_curve.empty() && a.cyclic) run.write_text(cyclic_curve, lab::cyclic_curve_csv(a));
    if (!failure_curve.empty() && a.failure) run.write_text(failure_curve, lab::failure_curve_csv(a));
    if (!plot.empty()) io::run_gnuplot(lab::figure5_script(a, run.output(plot), title));
    run.emit_json(summary, out);
  });
}
