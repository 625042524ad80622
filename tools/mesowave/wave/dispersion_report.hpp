#pragma once
// What mw-dispersion writes, one builder per subcommand: the JSON summary, the
// metrics of the run record, the table, and the plot or signals where asked.
// A request holds the subcommand's options as given (units in the names, as on
// the command line); the builders check them, run the analysis and report.
//   theory     Pochhammer-Chree modes of a solid rod (rod paper Eq. 1, Figure 9)
//   lattice    the DEM chain's exact dispersion, w = 2 sqrt(K/m) |sin(k d/2)|
//   measure    group velocity of burst runs and its RSS against theory (rod Table 2)
//   bar-echo   bar velocity from a pulse-echo record (bar_echo.hpp) and its budget
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesowave/io/plot.hpp"
#include "mesowave/prov/run_record.hpp"
#include "mesowave/signal/signal.hpp"
#include "mesowave/wave/bar_echo.hpp"
#include "mesowave/wave/dispersion_output.hpp"

namespace mesowave::wave {

/// The bar or rod: all four for a Pochhammer-Chree theory. `experiment` (a study's
/// lab-data/<study>/experiment.toml whose specimen is a rod: experiment::rod_of) gives the four
/// not given; measure's echo then also takes its round trip, 2 L, unless --distance-mm gives one.
struct RodOptions {
  std::optional<double> E_GPa, nu, density_kg_m3, radius_mm;
  std::filesystem::path experiment;
  bool complete() const { return E_GPa && nu && density_kg_m3 && radius_mm; }
  bool any() const { return E_GPa || nu || density_kg_m3 || radius_mm; }
};

/// What every subcommand reports besides its files.
struct DispersionReport {
  nlohmann::ordered_json summary;
  std::vector<prov::MetricRecord> metrics;
  std::vector<std::filesystem::path> inputs;  ///< every file read, for the run record
  std::string csv;                            ///< the subcommand's table
};

struct TheoryRequest {
  RodOptions rod;
  double f_max_kHz = 500, df_kHz = 1, ka_step = 0.01;
  std::optional<double> f_min_kHz;  ///< default: the step
  int max_modes = 0;                ///< 0: every mode below f_max
  std::vector<std::string> overlays;  ///< LABEL=FILE.csv (columns f_kHz, c_group_m_s)
  std::filesystem::path plot;         ///< "" for none; .png or .svg
  std::string plot_f_range, plot_c_range;  ///< "LO,HI" [kHz], [m/s]; "" for gnuplot's choice
  std::string plot_key = "outside right top";  ///< gnuplot words, spaces or commas
};
struct TheoryReport : DispersionReport {
  std::optional<PochhammerChree> rod;
  std::vector<DispersionPoint> points;  ///< the table's rows (csv, write_dispersion_h5)
  std::optional<io::PlotSpec> plot;     ///< when the request names a plot
};
TheoryReport theory_report(const TheoryRequest& request);

struct LatticeRequest {
  std::optional<double> mass_kg, stiffness_N_m, spacing_mm;                   ///< the chain directly, or
  std::optional<double> sphere_radius_mm, particle_density_kg_m3, E_dem_GPa, spacing_R;  ///< the DEM's
  double f_max_kHz = 500, df_kHz = 1;
  std::string label = "chain";
};
DispersionReport lattice_report(const LatticeRequest& request);

struct MeasureReportRequest {
  std::vector<std::string> runs;   ///< FILE (recording its burst frequency) or FREQ_kHz=FILE
  std::filesystem::path spacetime;  ///< or one space-time record (2D FFT ridge)
  std::string method = "echo";
  std::vector<std::string> stations;  ///< default {"S"}
  double distance_mm = 0, cycles = 5, f_min_kHz = 10, f_max_kHz = 300;
  RodOptions rod;                   ///< theory from the material, or
  std::filesystem::path theory_csv;  ///< from an mw-dispersion theory table
  std::string band_kHz;             ///< "LO,HI" of the RSS; "" for every point
  std::string label;                ///< "" for the file names
};
DispersionReport measure_report(const MeasureReportRequest& request);

struct BarEchoRequest {
  std::filesystem::path record;
  std::string column;
  double path_mm = 0, path_uncertainty_mm = 0;  ///< the round trip and its standard uncertainty
  RodOptions rod;  ///< E and density give c0; all four, the Pochhammer-Chree echo
};
struct BarEchoReport : DispersionReport {
  signal::Signal record;
  BarEchoResult result;
};
BarEchoReport bar_echo_report(const BarEchoRequest& request);
/// The record and the theory's echo, to write as a signal file; InputError without a theory.
std::vector<signal::Signal> bar_echo_signals(const BarEchoReport& report);

}  // namespace mesowave::wave
