// mw-synth - synthetic raw lab data with a stated ground truth, deterministic
// by seed: micro-CT stacks and microscope face images with pores at a given
// volume fraction, cyclic and failure compression records for a given E,
// strength and crosshead multiplier, UPV waveforms with given times of flight.
// Every run writes a truth TOML (source = "synthetic") beside the data.
//
//   mw-synth ct --stack ct-stack.tif --truth ct-truth.toml --porosity-pct 7 --seed 7
//   mw-synth compression --cyclic cyclic.csv --failure failure.csv --truth truth.toml
#include <sstream>

#include "mesowave/app/tool.hpp"
#include "mesowave/io/image.hpp"
#include "mesowave/lab/synthetic_report.hpp"

using namespace mesowave;

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
  lab::SynthesisRequest r;
  std::filesystem::path truth, out;
  auto& cli = tool.cli();
  cli.add_option("kind", r.kind, "What to make: ct, faces, compression or upv")
      ->required()
      ->check(CLI::IsMember({"ct", "faces", "compression", "upv"}));
  cli.add_option("--truth", truth, "Ground truth TOML to write")->required()->type_name("FILE");
  cli.add_option("--seed", r.seed, "Random seed (same seed, same bits)")->capture_default_str();
  app::add_out_option(cli, out, "the truth as JSON");
  auto* g = "ct and faces";
  cli.add_option("--stack", r.stack, "ct: multi-page TIFF to write")->group(g)->type_name("FILE");
  cli.add_option("--prefix", r.prefix, "faces: write PREFIX-1.png .. PREFIX-N.png")->group(g)->type_name("PATH");
  cli.add_option("--count", r.count, "faces: number of face images")->group(g)->capture_default_str();
  cli.add_option("--porosity-pct", r.porosity_pct, "Target pore volume (area) fraction [%]")->group(g)->capture_default_str();
  cli.add_option("--pore-shape", r.pore_shape, "sphere or irregular (clusters of overlapping spheres)")
      ->group(g)->check(CLI::IsMember({"sphere", "irregular"}))->capture_default_str();
  cli.add_option("--pore-radius-px", r.pore_radius_px, "Smallest,largest pore radius [px] (log-uniform)")
      ->group(g)->delimiter(',')->expected(2);
  cli.add_option("--size-px", r.size_px, "ct: specimen width in a slice (default 96); faces: image side (default 256)")->group(g);
  cli.add_option("--margin-px", r.margin_px, "ct: air margin around the specimen [px]")->group(g)->capture_default_str();
  cli.add_option("--slices", r.slices, "ct: number of slices")->group(g)->capture_default_str();
  cli.add_option("--pixel-size-um", r.pixel_um, "Voxel / pixel size [um] (default 50 for ct, 10 for faces)")->group(g);
  cli.add_option("--noise", r.noise, "Gaussian noise SD [gray levels] (default 1500 for 16-bit ct, 5 for faces)")->group(g);
  g = "compression";
  cli.add_option("--cyclic", r.cyclic, "Cyclic test CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--failure", r.failure, "Failure test CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--E-GPa", r.E_GPa, "Static modulus of the specimen [GPa]")->group(g)->capture_default_str();
  cli.add_option("--strength-MPa", r.strength_MPa, "Compressive strength [MPa]")->group(g)->capture_default_str();
  cli.add_option("--upper-stress-MPa", r.upper_stress_MPa, "Upper stress of the cycles [MPa]")->group(g)->capture_default_str();
  cli.add_option("--lower-stress-MPa", r.lower_stress_MPa, "Lower stress of the cycles [MPa]")->group(g)->capture_default_str();
  cli.add_option("--cyclic-stress-rate-MPa-s", r.cyclic_rate_MPa_s, "Loading rate of the cycles [MPa/s]")->group(g)->capture_default_str();
  cli.add_option("--failure-stress-rate-MPa-s", r.failure_rate_MPa_s, "Loading rate to failure [MPa/s]")->group(g)->capture_default_str();
  cli.add_option("--hold-s", r.compression.hold_s, "Hold at each stress level [s]")->group(g)->capture_default_str();
  cli.add_option("--cycles", r.compression.cycles, "Loading cycles")->group(g)->capture_default_str();
  cli.add_option("--side-mm", r.side_mm, "Cube side [mm] (area side^2, height side)")->group(g)->capture_default_str();
  cli.add_option("--gauge-length-mm", r.gauge_length_mm, "Extensometer gauge length [mm]")->group(g)->capture_default_str();
  cli.add_option("--crosshead-multiplier", r.crosshead_multiplier, "Extensometer strain / crosshead strain")->group(g)->capture_default_str();
  cli.add_option("--sample-rate-Hz", r.compression.sample_rate_Hz, "Sampling of the cyclic test [Hz]")->group(g)->capture_default_str();
  cli.add_option("--skip-cycle", r.skip_cycle, "Hard case: leave this cycle out (hold at the lower stress)")->group(g);
  cli.add_option("--dropout-channel", r.dropout_channel, "Hard case: extensometer 1 or 2 drops out...")->group(g);
  cli.add_option("--dropout-time-s", r.dropout_time_s, "...from this time on...")->group(g);
  cli.add_flag("--dropout-stuck", r.dropout_stuck, "...stuck at its last value (default: empty fields)")->group(g);
  g = "upv";
  cli.add_option("--p-wave", r.p_wave, "P-wave record CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--s-wave", r.s_wave, "S-wave record CSV to write")->group(g)->type_name("FILE");
  cli.add_option("--path-mm", r.path_mm, "Distance between the transducers [mm]")->group(g)->capture_default_str();
  cli.add_option("--t-p-us", r.t_p_us, "P-wave time of flight [us]")->group(g)->capture_default_str();
  cli.add_option("--t-s-us", r.t_s_us, "S-wave time of flight [us]")->group(g)->capture_default_str();
  cli.add_option("--p-transducer-frequency-kHz", r.p_frequency_kHz, "P transducer frequency [kHz]")->group(g)->capture_default_str();
  cli.add_option("--s-transducer-frequency-kHz", r.s_frequency_kHz, "S transducer frequency [kHz]")->group(g)->capture_default_str();
  cli.add_option("--snr-dB", r.snr_dB, "20 log10(peak / noise RMS)")->group(g)->capture_default_str();
  cli.add_option("--attenuation-dB", r.attenuation_dB, "Amplitude loss over the path [dB]")->group(g)->capture_default_str();
  cli.add_option("--bandwidth-factor", r.bandwidth_factor, "Causal low-pass corner / transducer frequency (0: none)")
      ->group(g)->capture_default_str();
  cli.add_option("--delay-us", r.delay_us, "Transducer + couplant delay inside the recorded onset [us]")->group(g)->capture_default_str();
  cli.add_option("--pretrigger-us", r.pretrigger_us, "Noise before the trigger [us]")->group(g)->capture_default_str();
  cli.add_option("--duration-us", r.duration_us, "Record length after the trigger [us]")->group(g)->capture_default_str();
  cli.add_option("--dt-us", r.dt_us, "Sample interval [us]")->group(g)->capture_default_str();
  cli.add_option("--s-precursor", r.s_precursor, "Peak of an early P arrival on the S record, relative to the S peak (0: none)")
      ->group(g)->capture_default_str();

  std::ostringstream command;
  for (int i = 0; i < argc; ++i) command << (i ? " " : "") << (i == 0 ? "mw-synth" : argv[i]);

  return tool.run(argc, argv, [&](app::Run& run) {
    const auto made = lab::synthesize(r);
    if (made.stack) io::write_tiff_gray_stack(run.output(made.stack->first), made.stack->second);
    for (const auto& [file, image] : made.images) io::write_png_gray(run.output(file), image);
    for (const auto& [file, text] : made.texts) run.write_text(file, text);
    run.write_text(truth, lab::truth_toml(made.title, command.str(), made.entries));
    run.emit_json(made.summary, out);
  });
}
