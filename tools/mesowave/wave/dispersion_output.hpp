#pragma once
// Tables, files, plots and summaries of dispersion curves, shared by
// mw-dispersion and the rod study: CSV (f_kHz, k_rad_m, ka, c_phase_m_s,
// c_group_m_s), HDF5 (one group per curve) and the group-velocity plot.
#include <filesystem>
#include <functional>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mesowave/wave/group_velocity.hpp"
#include "mesowave/wave/lattice.hpp"
#include "mesowave/io/plot.hpp"
#include "mesowave/wave/pochhammer_chree.hpp"

namespace mesowave::wave {

/// A lattice (DEM chain) curve sampled in frequency.
struct LatticeCurve {
  std::string label;  ///< "1.03R"
  MassSpringChain chain;
  std::vector<LatticePoint> points;
};
LatticeCurve lattice_curve(std::string label, const MassSpringChain& chain, const std::vector<double>& f_Hz);

/// A measured or simulated group-velocity curve read for an overlay.
struct VelocityCurve {
  std::string label;
  std::vector<double> f_Hz, c_group_m_s;
};
/// Reads columns f_kHz and c_group_m_s of a CSV (lattice, measure or theory output;
/// a `mode` column, if present, keeps only mode 1 rows).
VelocityCurve read_velocity_curve(const std::filesystem::path& csv, std::string label);

/// Frequencies f_min, f_min + df, ... <= f_max (InputError for a bad grid).
std::vector<double> frequency_grid(double f_min_Hz, double f_max_Hz, double df_Hz);

std::string theory_csv(const std::vector<DispersionPoint>& points, double radius_m);
std::string lattice_csv(const LatticeCurve& curve);

/// HDF5: /theory (columns as datasets, material attributes) and /lattice/<label>.
void write_dispersion_h5(const std::filesystem::path& path, const PochhammerChree& pc,
                         const std::vector<DispersionPoint>& points, const std::vector<LatticeCurve>& lattices = {});

/// Group velocity against frequency: one line per mode branch (backward branches
/// dashed), then the lattice and overlay curves.
io::PlotSpec group_velocity_plot(const std::string& title, const std::vector<DispersionPoint>& theory,
                             const std::vector<LatticeCurve>& lattices, const std::vector<VelocityCurve>& overlays);

/// A string attribute of a signal file's root ("burst_frequency_Hz"), if present.
std::optional<std::string> signal_file_attribute(const std::filesystem::path& path, const std::string& name);

/// Reads /spacetime of an mw-fem space-time file (uniform positions required).
SpaceTimeRecord read_spacetime_file(const std::filesystem::path& path);

/// Group velocity of L(0,1) from Pochhammer-Chree theory at each frequency.
std::vector<double> l01_group_velocity(const PochhammerChree& pc, const std::vector<double>& f_Hz);

/// Linear interpolation of the L(0,1) group velocity in a theory CSV (mw-dispersion
/// theory --csv); InputError outside its frequency range.
std::function<double(double)> theory_from_csv(const std::filesystem::path& csv);

/// Cut-offs, zero-group-velocity points, L(0,1) group-velocity minimum, speeds.
nlohmann::ordered_json theory_summary(const PochhammerChree& pc, const DispersionTrace& trace);

}  // namespace mesowave::wave
