// mw-synth - synthetic raw lab data with a stated ground truth, deterministic
// by seed: micro-CT stacks and microscope face images with pores at a given
// volume fraction, cyclic and failure compression records for a given E,
// strength and crosshead multiplier, UPV waveforms with given times of flight.
// Every run writes a truth TOML (source = "synthetic") beside the data.
//
//   mw-synth ct --stack ct-stack.tif --truth ct-truth.toml --porosity-pct 7 --seed 7
//   mw-synth compression --cyclic cyclic.csv --failure failure.csv --truth truth.toml
#include <cmath>
#include <optional>
#include <sstream>

#include "mesowave/app/tool.hpp"
#include "mesowave/core/check.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/io/image.hpp"
#include "mesowave/lab/synthetic_compression.hpp"
#include "mesowave/lab/synthetic_pores.hpp"
#include "mesowave/lab/synthetic_truth.hpp"
#include "mesowave/lab/synthetic_upv.hpp"

using namespace mesowave;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  app::Tool tool(
      "mw-synth",
      "Synthetic raw lab data with a stated ground truth, deterministic by --seed (own generator: xoshiro256**). "
      "KIND is one of:\n"
      "  ct           micro-CT stack (multi-page 16-bit TIFF): mortar with dark pores at --porosity-pct, air margin\n"
      "  faces        microscope face images (8-bit PNG): plaster-filled (bright) pores at --porosity-pct\n"
      "  compression  cyclic test (EN 12390-13 method B) and failure test records (CSV) for --E-GPa, --strength-MPa,\n"
      "               --crosshead-multiplier, with noise and EN 1992-1-1 Eq. (3.14) softening near failure\n"
      "  upv          P- and S-wave records (CSV t_us, amplitude_V) with --t-p-us / --t-s-us, attenuation, noise\n"
      "The truth (exact pore coverage drawn, E, strength, multiplier, onsets) goes to --truth as lab-data TOML.\n\n"
      "  mw-synth ct --stack raw/ct-stack.tif --truth raw/ct-truth.toml --seed 7\n"
      "  mw-synth faces --prefix raw/face --count 3 --truth raw/faces-truth.toml --seed 11\n"
      "  mw-synth compression --cyclic raw/cyclic.csv --failure raw/failure.csv --truth raw/compression-truth.toml\n"
      "  mw-synth upv --p-wave raw/upv-p.csv --s-wave raw/upv-s.csv --truth raw/upv-truth.toml --snr-dB 20");
  std::string kind;
  fs::path truth, stack, prefix, cyclic, failure, p_wave, s_wave, out;
  std::uint64_t seed = 1;
  double porosity_pct = 7.0;
  std::string shape = "sphere";
  // ct / faces
  int size_px = 0, margin_px = 6, slices = 32, count = 3;
  double pixel_um = 0;
  std::vector<double> pore_radius_px;
  std::optional<double> noise;
  // compression
  lab::SyntheticCompressionSpec c;
  double E_GPa = 27.42, strength_MPa = 66.0, upper_MPa = 16.7, lower_MPa = 0.5, rate = 0.3, frate = 0.6,
         gauge_mm = 75, side_mm = 150, multiplier = 1.0 / 4.5, drop_time = 0;
  int skip_cycle = 0, drop_channel = 0;
  bool drop_stuck = false;
  // upv
  double path_mm = 150, t_p_us = 35, t_s_us = 55.1, f_p_kHz = 54, f_s_kHz = 40, snr_dB = 20, attenuation_dB = 6,
         delay_us = 0, pretrigger_us = 50, duration_us = 250, dt_us = 0.1, bandwidth_factor = 0, precursor = 0;

  auto& cli = tool.cli();
  cli.add_option("kind", kind, "What to make: ct, faces, compression or upv")
      ->required()
      ->check(CLI::IsMember({"ct", "faces", "compression", "upv"}));
  cli.add_option("--truth", truth, "Ground truth TOML to write")->required()->type_name("FILE");
  cli.add_option("--seed", seed, "Random seed (same seed, same bits)")->capture_default_str();
  app::add_out_option(cli, out, "the truth as JSON");
  auto* g = "ct and faces";
  cli.add_option("--stack", stack, "ct: multi-page TIFF to write")->group(g)->type_name("FILE");
  cli.add_option("--prefix", prefix, "faces: write PREFIX-1.png .. PREFIX-N.png")->group(g)->type_name("PATH");
  cli.add_option("--count", count, "faces: number of face images")->group(g)->capture_default_str();
  cli.add_option("--porosity-pct", porosity_pct, "Target pore volume (area) fraction [%]")->group(g)->capture_default_str();
  cli.add_option("--pore-shape", shape, "sphere or irregular (clusters of overlapping spheres)")
      ->group(g)->check(CLI::IsMember({"sphere", "irregular"}))->capture_default_str();
  cli.add_option("--pore-radius-px", pore_radius_px, "Smallest,largest pore radius [px] (log-uniform)")
      ->group(g)->delimiter(',')->expected(2);
  cli.add_option("--size-px", size_px, "ct: specimen width in a slice (default 96); faces: image side (default 256)")->group(g);
  cli.add_option("--margin-px", margin_px, "ct: air margin around the specimen [px]")->group(g)->capture_default_str();
  cli.add_option("--slices", slices, "ct: number of slices")->group(g)->capture_default_str();
  cli.add_option("--pixel-size-um", pixel_um, "Voxel / pixel size [um] (default 50 for ct, 10 for faces)")->group(g);
  cli.add_option("--noise", noise, "Gaussian noise SD [gray levels] (default 1500 for 16-bit ct, 5 for faces)")->group(g);
  g = "compression";
  cli.add_option("--cyclic", cyclic, "Cyclic test CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--failure", failure, "Failure test CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--E-GPa", E_GPa, "Static modulus of the specimen [GPa]")->group(g)->capture_default_str();
  cli.add_option("--strength-MPa", strength_MPa, "Compressive strength [MPa]")->group(g)->capture_default_str();
  cli.add_option("--upper-stress-MPa", upper_MPa, "Upper stress of the cycles [MPa]")->group(g)->capture_default_str();
  cli.add_option("--lower-stress-MPa", lower_MPa, "Lower stress of the cycles [MPa]")->group(g)->capture_default_str();
  cli.add_option("--cyclic-stress-rate-MPa-s", rate, "Loading rate of the cycles [MPa/s]")->group(g)->capture_default_str();
  cli.add_option("--failure-stress-rate-MPa-s", frate, "Loading rate to failure [MPa/s]")->group(g)->capture_default_str();
  cli.add_option("--hold-s", c.hold_s, "Hold at each stress level [s]")->group(g)->capture_default_str();
  cli.add_option("--cycles", c.cycles, "Loading cycles")->group(g)->capture_default_str();
  cli.add_option("--side-mm", side_mm, "Cube side [mm] (area side^2, height side)")->group(g)->capture_default_str();
  cli.add_option("--gauge-length-mm", gauge_mm, "Extensometer gauge length [mm]")->group(g)->capture_default_str();
  cli.add_option("--crosshead-multiplier", multiplier, "Extensometer strain / crosshead strain")->group(g)->capture_default_str();
  cli.add_option("--sample-rate-Hz", c.sample_rate_Hz, "Sampling of the cyclic test [Hz]")->group(g)->capture_default_str();
  cli.add_option("--skip-cycle", skip_cycle, "Hard case: leave this cycle out (hold at the lower stress)")->group(g);
  cli.add_option("--dropout-channel", drop_channel, "Hard case: extensometer 1 or 2 drops out...")->group(g);
  cli.add_option("--dropout-time-s", drop_time, "...from this time on...")->group(g);
  cli.add_flag("--dropout-stuck", drop_stuck, "...stuck at its last value (default: empty fields)")->group(g);
  g = "upv";
  cli.add_option("--p-wave", p_wave, "P-wave record CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--s-wave", s_wave, "S-wave record CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--path-mm", path_mm, "Distance between the transducers [mm]")->group(g)->capture_default_str();
  cli.add_option("--t-p-us", t_p_us, "P-wave time of flight [us]")->group(g)->capture_default_str();
  cli.add_option("--t-s-us", t_s_us, "S-wave time of flight [us]")->group(g)->capture_default_str();
  cli.add_option("--p-transducer-frequency-kHz", f_p_kHz, "P transducer frequency [kHz]")->group(g)->capture_default_str();
  cli.add_option("--s-transducer-frequency-kHz", f_s_kHz, "S transducer frequency [kHz]")->group(g)->capture_default_str();
  cli.add_option("--snr-dB", snr_dB, "20 log10(peak / noise RMS)")->group(g)->capture_default_str();
  cli.add_option("--attenuation-dB", attenuation_dB, "Amplitude loss over the path [dB]")->group(g)->capture_default_str();
  cli.add_option("--bandwidth-factor", bandwidth_factor, "Causal low-pass corner / transducer frequency (0: none)")
      ->group(g)->capture_default_str();
  cli.add_option("--delay-us", delay_us, "Transducer + couplant delay inside the recorded onset [us]")->group(g)->capture_default_str();
  cli.add_option("--pretrigger-us", pretrigger_us, "Noise before the trigger [us]")->group(g)->capture_default_str();
  cli.add_option("--duration-us", duration_us, "Record length after the trigger [us]")->group(g)->capture_default_str();
  cli.add_option("--dt-us", dt_us, "Sample interval [us]")->group(g)->capture_default_str();
  cli.add_option("--s-precursor", precursor, "Peak of an early P arrival on the S record, relative to the S peak (0: none)")
      ->group(g)->capture_default_str();

  std::ostringstream command;
  for (int i = 0; i < argc; ++i) command << (i ? " " : "") << (i == 0 ? "mw-synth" : argv[i]);

  return tool.run(argc, argv, [&](app::Run& run) {
    const auto pore_shape = shape == "irregular" ? lab::PoreShape::irregular : lab::PoreShape::sphere;
    require_in_range("--porosity-pct", porosity_pct, 0.01, 60, "%");
    nlohmann::ordered_json result;
    result["kind"] = kind;
    result["seed"] = seed;
    std::vector<lab::TruthEntry> entries;
    std::string title;

    if (kind == "ct") {
      if (stack.empty()) throw InputError("ct needs --stack FILE.tif");
      lab::SyntheticCtSpec spec;
      spec.specimen_px = size_px ? size_px : spec.specimen_px;
      spec.margin_px = margin_px;
      spec.slices = slices;
      if (pixel_um > 0) spec.voxel_um = pixel_um;
      spec.porosity = porosity_pct / 100.0;
      spec.shape = pore_shape;
      if (!pore_radius_px.empty()) {
        spec.pore_radius_min_px = pore_radius_px[0];
        spec.pore_radius_max_px = pore_radius_px[1];
      }
      if (noise) spec.noise_sd = *noise;
      spec.seed = seed;
      const auto ct = lab::synthetic_ct_stack(spec);
      io::write_tiff_gray_stack(run.output(stack), ct.slices);
      const auto& r = ct.specimen_roi;
      const std::string roi = std::to_string(r[0]) + "," + std::to_string(r[1]) + "," + std::to_string(r[2]) + "," +
                              std::to_string(r[3]);
      title = "Synthetic micro-CT stack " + stack.filename().string() + ": " + std::to_string(spec.slices) +
              " slices of " + std::to_string(spec.specimen_px + 2 * spec.margin_px) + " px, specimen ROI " + roi +
              " (x0,y0,w,h), pores dark";
      entries = {{"true_porosity", 100 * ct.true_porosity, "pct",
                  "pore volume fraction of the specimen block (ROI " + roi + " in every slice): exact coverage of the " +
                      std::to_string(ct.pores) + " " + shape + " voids drawn"},
                 {"target_porosity", porosity_pct, "pct", "target the generator drew voids up to"},
                 {"voxel_size", spec.voxel_um, "um", "voxel edge"},
                 {"slice_spacing", spec.voxel_um, "um", "distance between slices (cubic voxels)"},
                 {"roi_x0", double(r[0]), "px", "specimen ROI, left column"},
                 {"roi_y0", double(r[1]), "px", "specimen ROI, top row"},
                 {"roi_width", double(r[2]), "px", "specimen ROI width"},
                 {"roi_height", double(r[3]), "px", "specimen ROI height"}};
      for (std::size_t z = 0; z < ct.slice_porosity.size(); ++z)
        entries.push_back({"true_porosity_slice_" + std::to_string(z + 1), 100 * ct.slice_porosity[z], "pct",
                           "exact pore coverage of slice " + std::to_string(z + 1) + " inside the ROI"});
      result["true_porosity_pct"] = 100 * ct.true_porosity;
      result["pores"] = ct.pores;
      result["roi"] = roi;
    } else if (kind == "faces") {
      if (prefix.empty()) throw InputError("faces needs --prefix PATH (writes PATH-1.png ...)");
      if (count < 1) throw InputError("--count must be at least 1");
      double sum = 0;
      std::vector<lab::TruthEntry> per_face;
      for (int i = 1; i <= count; ++i) {
        lab::SyntheticFaceSpec spec;
        if (size_px) spec.width_px = spec.height_px = size_px;
        if (pixel_um > 0) spec.pixel_um = pixel_um;
        spec.porosity = porosity_pct / 100.0;
        spec.shape = pore_shape;
        if (!pore_radius_px.empty()) {
          spec.pore_radius_min_px = pore_radius_px[0];
          spec.pore_radius_max_px = pore_radius_px[1];
        }
        if (noise) spec.noise_sd = *noise;
        spec.seed = seed * 1000 + std::uint64_t(i);
        const auto face = lab::synthetic_face(spec);
        const fs::path file = prefix.string() + "-" + std::to_string(i) + ".png";
        io::write_png_gray(run.output(file), face.image);
        sum += face.true_porosity;
        per_face.push_back({"true_porosity_face_" + std::to_string(i), 100 * face.true_porosity, "pct",
                            file.filename().string() + ": exact plaster-filled pore area fraction (" +
                                std::to_string(face.pores) + " " + shape + " pores)"});
      }
      title = "Synthetic microscope face images " + prefix.filename().string() + "-1.png .. -" + std::to_string(count) +
              ".png: plaster-filled pores bright";
      entries = {{"true_porosity", 100 * sum / count, "pct", "pore area fraction of all faces together (equal sizes)"},
                 {"target_porosity", porosity_pct, "pct", "target area fraction of every face"},
                 {"pixel_size", pixel_um > 0 ? pixel_um : lab::SyntheticFaceSpec{}.pixel_um, "um", "pixel edge"}};
      entries.insert(entries.end(), per_face.begin(), per_face.end());
      result["true_porosity_pct"] = 100 * sum / count;
    } else if (kind == "compression") {
      if (cyclic.empty() || failure.empty()) throw InputError("compression needs --cyclic FILE and --failure FILE");
      c.E_Pa = require_positive("--E-GPa", E_GPa, "GPa") * units::GPa;
      c.strength_Pa = require_positive("--strength-MPa", strength_MPa, "MPa") * units::MPa;
      c.upper_stress_Pa = upper_MPa * units::MPa;
      c.lower_stress_Pa = lower_MPa * units::MPa;
      c.cyclic_rate_Pa_s = rate * units::MPa;
      c.failure_rate_Pa_s = frate * units::MPa;
      c.side_m = require_positive("--side-mm", side_mm, "mm") * units::mm;
      c.gauge_length_m = require_positive("--gauge-length-mm", gauge_mm, "mm") * units::mm;
      c.crosshead_multiplier = multiplier;
      c.skip_cycle = skip_cycle;
      c.dropout_channel = drop_channel;
      c.dropout_time_s = drop_time;
      c.dropout_stuck = drop_stuck;
      c.seed = seed;
      const auto tests = lab::synthetic_compression_tests(c);
      const std::string label = lab::synthetic_record_label();
      run.write_text(cyclic, label + lab::compression_record_csv(tests.cyclic));
      run.write_text(failure, label + lab::compression_record_csv(tests.failure));
      title = "Synthetic compression tests of a " + format_number(side_mm) + " mm cube: " + cyclic.filename().string() +
              " (cyclic, EN 12390-13 method B) and " + failure.filename().string() + " (to failure)";
      entries = {{"true_E_st", E_GPa, "GPa", "modulus of every unloading/reloading cycle after the first loading"},
                 {"true_sigma_max", strength_MPa, "MPa", "peak of the failure test's stress programme"},
                 {"true_crosshead_multiplier", multiplier, "",
                  "extensometer strain / crosshead strain outside the platen seating"},
                 {"true_eps_c1", tests.eps_c1 * 1e3, "permille", "strain at the peak (EN 1992-1-1 Table 3.1)"},
                 {"side", side_mm, "mm", "cube side: loaded area side^2", "synthetic"},
                 {"specimen_height", side_mm, "mm", "cube: height = side", "synthetic"},
                 {"gauge_length", gauge_mm, "mm", "extensometer gauge length", "synthetic"},
                 {"upper_stress", upper_MPa, "MPa", "upper stress of the cycles", "synthetic"},
                 {"lower_stress", lower_MPa, "MPa", "lower stress of the cycles", "synthetic"},
                 {"hold", c.hold_s, "s", "hold at each level", "synthetic"}};
      result["true_E_st_GPa"] = E_GPa;
      result["true_sigma_max_MPa"] = strength_MPa;
      result["true_crosshead_multiplier"] = multiplier;
    } else {
      if (p_wave.empty() && s_wave.empty()) throw InputError("upv needs --p-wave FILE and/or --s-wave FILE");
      auto make = [&](const fs::path& file, double tof_us, double f_kHz, double pre, std::uint64_t s) {
        lab::SyntheticUpvSpec spec;
        spec.tof_s = tof_us * units::us;
        spec.delay_s = delay_us * units::us;
        spec.frequency_Hz = f_kHz * units::kHz;
        spec.bandwidth_Hz = bandwidth_factor * spec.frequency_Hz;
        spec.attenuation_dB = attenuation_dB;
        spec.snr_dB = snr_dB;
        spec.sample_interval_s = dt_us * units::us;
        spec.pretrigger_s = pretrigger_us * units::us;
        spec.duration_s = duration_us * units::us;
        spec.precursor_tof_s = pre > 0 ? t_p_us * units::us : 0.0;
        spec.precursor_fraction = pre;
        spec.seed = s;
        run.write_text(file, lab::synthetic_record_label() +
                                 lab::waveform_csv(lab::synthetic_upv_waveform(spec)));
      };
      if (!p_wave.empty()) make(p_wave, t_p_us, f_p_kHz, 0, seed);
      if (!s_wave.empty()) make(s_wave, t_s_us, f_s_kHz, precursor, seed + 1);
      title = "Synthetic UPV waveforms (time of flight = onset - delay)";
      entries = {{"true_t_p", t_p_us, "us", "P-wave time of flight (pulse onset minus the delay)"},
                 {"true_t_s", t_s_us, "us", "S-wave time of flight"},
                 {"path", path_mm, "mm", "distance between the transducers", "synthetic"},
                 {"delay", delay_us, "us", "transducer + couplant delay included in the recorded onsets", "synthetic"},
                 {"snr", snr_dB, "dB", "20 log10(peak / noise RMS)", "synthetic"},
                 {"attenuation", attenuation_dB, "dB", "amplitude loss over the path", "synthetic"}};
      result["true_t_p_us"] = t_p_us;
      result["true_t_s_us"] = t_s_us;
    }
    run.write_text(truth, lab::truth_toml(title, command.str(), entries));
    run.emit_json(result, out);
  });
}
