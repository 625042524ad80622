#include "mesowave/lab/synthetic_report.hpp"

#include "mesowave/core/check.hpp"
#include "mesowave/core/error.hpp"
#include "mesowave/core/format.hpp"
#include "mesowave/core/units.hpp"
#include "mesowave/lab/synthetic_pores.hpp"
#include "mesowave/lab/synthetic_upv.hpp"

namespace mesowave::lab {

namespace fs = std::filesystem;

namespace {

// The pore options ct and faces share, onto either generator's spec.
template <class PoreSpec>
void set_pores(PoreSpec& spec, const SynthesisRequest& q, PoreShape shape) {
  spec.porosity = q.porosity_pct / 100.0;
  spec.shape = shape;
  if (!q.pore_radius_px.empty()) {
    spec.pore_radius_min_px = q.pore_radius_px[0];
    spec.pore_radius_max_px = q.pore_radius_px[1];
  }
  if (q.noise) spec.noise_sd = *q.noise;
}

void ct(const SynthesisRequest& q, PoreShape shape, SynthesisProducts& p) {
  if (q.stack.empty()) throw InputError("ct needs --stack FILE.tif");
  SyntheticCtSpec spec;
  spec.specimen_px = q.size_px ? q.size_px : spec.specimen_px;
  spec.margin_px = q.margin_px;
  spec.slices = q.slices;
  if (q.pixel_um > 0) spec.voxel_um = q.pixel_um;
  set_pores(spec, q, shape);
  spec.seed = q.seed;
  auto stack = synthetic_ct_stack(spec);
  const auto& r = stack.specimen_roi;
  const std::string roi =
      std::to_string(r[0]) + "," + std::to_string(r[1]) + "," + std::to_string(r[2]) + "," + std::to_string(r[3]);
  p.title = "Synthetic micro-CT stack " + q.stack.filename().string() + ": " + std::to_string(spec.slices) +
            " slices of " + std::to_string(spec.specimen_px + 2 * spec.margin_px) + " px, specimen ROI " + roi +
            " (x0,y0,w,h), pores dark";
  p.entries = {{"true_porosity", 100 * stack.true_porosity, "pct",
                "pore volume fraction of the specimen block (ROI " + roi + " in every slice): exact coverage of the " +
                    std::to_string(stack.pores) + " " + q.pore_shape + " voids drawn"},
               {"target_porosity", q.porosity_pct, "pct", "target the generator drew voids up to"},
               {"voxel_size", spec.voxel_um, "um", "voxel edge"},
               {"slice_spacing", spec.voxel_um, "um", "distance between slices (cubic voxels)"},
               {"roi_x0", double(r[0]), "px", "specimen ROI, left column"},
               {"roi_y0", double(r[1]), "px", "specimen ROI, top row"},
               {"roi_width", double(r[2]), "px", "specimen ROI width"},
               {"roi_height", double(r[3]), "px", "specimen ROI height"}};
  for (std::size_t z = 0; z < stack.slice_porosity.size(); ++z)
    p.entries.push_back({"true_porosity_slice_" + std::to_string(z + 1), 100 * stack.slice_porosity[z], "pct",
                         "exact pore coverage of slice " + std::to_string(z + 1) + " inside the ROI"});
  p.summary["true_porosity_pct"] = 100 * stack.true_porosity;
  p.summary["pores"] = stack.pores;
  p.summary["roi"] = roi;
  p.stack = {q.stack, std::move(stack.slices)};
}

void faces(const SynthesisRequest& q, PoreShape shape, SynthesisProducts& p) {
  if (q.prefix.empty()) throw InputError("faces needs --prefix PATH (writes PATH-1.png ...)");
  if (q.count < 1) throw InputError("--count must be at least 1");
  double sum = 0;
  std::vector<TruthEntry> per_face;
  for (int i = 1; i <= q.count; ++i) {
    SyntheticFaceSpec spec;
    if (q.size_px) spec.width_px = spec.height_px = q.size_px;
    if (q.pixel_um > 0) spec.pixel_um = q.pixel_um;
    set_pores(spec, q, shape);
    spec.seed = q.seed * 1000 + std::uint64_t(i);
    auto face = synthetic_face(spec);
    const fs::path file = q.prefix.string() + "-" + std::to_string(i) + ".png";
    sum += face.true_porosity;
    per_face.push_back({"true_porosity_face_" + std::to_string(i), 100 * face.true_porosity, "pct",
                        file.filename().string() + ": exact plaster-filled pore area fraction (" +
                            std::to_string(face.pores) + " " + q.pore_shape + " pores)"});
    p.images.emplace_back(file, std::move(face.image));
  }
  p.title = "Synthetic microscope face images " + q.prefix.filename().string() + "-1.png .. -" +
            std::to_string(q.count) + ".png: plaster-filled pores bright";
  p.entries = {{"true_porosity", 100 * sum / q.count, "pct", "pore area fraction of all faces together (equal sizes)"},
               {"target_porosity", q.porosity_pct, "pct", "target area fraction of every face"},
               {"pixel_size", q.pixel_um > 0 ? q.pixel_um : SyntheticFaceSpec{}.pixel_um, "um", "pixel edge"}};
  p.entries.insert(p.entries.end(), per_face.begin(), per_face.end());
  p.summary["true_porosity_pct"] = 100 * sum / q.count;
}

void compression(const SynthesisRequest& q, SynthesisProducts& p) {
  if (q.cyclic.empty() || q.failure.empty()) throw InputError("compression needs --cyclic FILE and --failure FILE");
  auto c = q.compression;
  c.E_Pa = require_positive("--E-GPa", q.E_GPa, "GPa") * units::GPa;
  c.strength_Pa = require_positive("--strength-MPa", q.strength_MPa, "MPa") * units::MPa;
  c.upper_stress_Pa = q.upper_stress_MPa * units::MPa;
  c.lower_stress_Pa = q.lower_stress_MPa * units::MPa;
  c.cyclic_rate_Pa_s = q.cyclic_rate_MPa_s * units::MPa;
  c.failure_rate_Pa_s = q.failure_rate_MPa_s * units::MPa;
  c.side_m = require_positive("--side-mm", q.side_mm, "mm") * units::mm;
  c.gauge_length_m = require_positive("--gauge-length-mm", q.gauge_length_mm, "mm") * units::mm;
  c.crosshead_multiplier = q.crosshead_multiplier;
  c.skip_cycle = q.skip_cycle;
  c.dropout_channel = q.dropout_channel;
  c.dropout_time_s = q.dropout_time_s;
  c.dropout_stuck = q.dropout_stuck;
  c.seed = q.seed;
  const auto tests = synthetic_compression_tests(c);
  p.texts = {{q.cyclic, synthetic_record_label() + compression_record_csv(tests.cyclic)},
             {q.failure, synthetic_record_label() + compression_record_csv(tests.failure)}};
  p.title = "Synthetic compression tests of a " + format_number(q.side_mm) + " mm cube: " +
            q.cyclic.filename().string() + " (cyclic, EN 12390-13 method B) and " + q.failure.filename().string() +
            " (to failure)";
  p.entries = {{"true_E_st", q.E_GPa, "GPa", "modulus of every unloading/reloading cycle after the first loading"},
               {"true_sigma_max", q.strength_MPa, "MPa", "peak of the failure test's stress programme"},
               {"true_crosshead_multiplier", q.crosshead_multiplier, "",
                "extensometer strain / crosshead strain outside the platen seating"},
               {"true_eps_c1", tests.eps_c1 * 1e3, "permille", "strain at the peak (EN 1992-1-1 Table 3.1)"},
               {"side", q.side_mm, "mm", "cube side: loaded area side^2", "synthetic"},
               {"specimen_height", q.side_mm, "mm", "cube: height = side", "synthetic"},
               {"gauge_length", q.gauge_length_mm, "mm", "extensometer gauge length", "synthetic"},
               {"upper_stress", q.upper_stress_MPa, "MPa", "upper stress of the cycles", "synthetic"},
               {"lower_stress", q.lower_stress_MPa, "MPa", "lower stress of the cycles", "synthetic"},
               {"hold", c.hold_s, "s", "hold at each level", "synthetic"}};
  p.summary["true_E_st_GPa"] = q.E_GPa;
  p.summary["true_sigma_max_MPa"] = q.strength_MPa;
  p.summary["true_crosshead_multiplier"] = q.crosshead_multiplier;
}

void upv(const SynthesisRequest& q, SynthesisProducts& p) {
  if (q.p_wave.empty() && q.s_wave.empty()) throw InputError("upv needs --p-wave FILE and/or --s-wave FILE");
  auto make = [&](const fs::path& file, double tof_us, double f_kHz, double precursor, std::uint64_t seed) {
    SyntheticUpvSpec spec;
    spec.tof_s = tof_us * units::us;
    spec.delay_s = q.delay_us * units::us;
    spec.frequency_Hz = f_kHz * units::kHz;
    spec.bandwidth_Hz = q.bandwidth_factor * spec.frequency_Hz;
    spec.attenuation_dB = q.attenuation_dB;
    spec.snr_dB = q.snr_dB;
    spec.sample_interval_s = q.dt_us * units::us;
    spec.pretrigger_s = q.pretrigger_us * units::us;
    spec.duration_s = q.duration_us * units::us;
    spec.precursor_tof_s = precursor > 0 ? q.t_p_us * units::us : 0.0;
    spec.precursor_fraction = precursor;
    spec.seed = seed;
    p.texts.emplace_back(file, synthetic_record_label() + waveform_csv(synthetic_upv_waveform(spec)));
  };
  if (!q.p_wave.empty()) make(q.p_wave, q.t_p_us, q.p_frequency_kHz, 0, q.seed);
  if (!q.s_wave.empty()) make(q.s_wave, q.t_s_us, q.s_frequency_kHz, q.s_precursor, q.seed + 1);
  p.title = "Synthetic UPV waveforms (time of flight = onset - delay)";
  p.entries = {{"true_t_p", q.t_p_us, "us", "P-wave time of flight (pulse onset minus the delay)"},
               {"true_t_s", q.t_s_us, "us", "S-wave time of flight"},
               {"path", q.path_mm, "mm", "distance between the transducers", "synthetic"},
               {"delay", q.delay_us, "us", "transducer + couplant delay included in the recorded onsets", "synthetic"},
               {"snr", q.snr_dB, "dB", "20 log10(peak / noise RMS)", "synthetic"},
               {"attenuation", q.attenuation_dB, "dB", "amplitude loss over the path", "synthetic"}};
  p.summary["true_t_p_us"] = q.t_p_us;
  p.summary["true_t_s_us"] = q.t_s_us;
}

}  // namespace

SynthesisProducts synthesize(const SynthesisRequest& q) {
  const auto shape = q.pore_shape == "irregular" ? PoreShape::irregular : PoreShape::sphere;
  require_in_range("--porosity-pct", q.porosity_pct, 0.01, 60, "%");
  SynthesisProducts p;
  p.summary["kind"] = q.kind;
  p.summary["seed"] = q.seed;
  if (q.kind == "ct") ct(q, shape, p);
  else if (q.kind == "faces") faces(q, shape, p);
  else if (q.kind == "compression") compression(q, p);
  else if (q.kind == "upv") upv(q, p);
  else throw InputError("kind '" + q.kind + "' must be ct, faces, compression or upv");
  return p;
}

}  // namespace mesowave::lab
