#pragma once
// What mw-synth makes: synthetic raw lab data with a stated ground truth,
// deterministic by seed (core/random.hpp's XoshiroRandom) - a micro-CT stack,
// microscope face images, cyclic and failure compression records, or UPV
// waveforms - with the truth entries, the title of the truth file and a JSON
// summary. The request is in the units the options take (%, px, um, GPa,
// MPa, mm, us, kHz, dB); nothing is written here.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesowave/io/image.hpp"
#include "mesowave/lab/synthetic_compression.hpp"
#include "mesowave/lab/synthetic_truth.hpp"

namespace mesowave::lab {

struct SynthesisRequest {
  std::string kind;            ///< ct | faces | compression | upv
  std::uint64_t seed = 1;
  std::filesystem::path stack, prefix, cyclic, failure, p_wave, s_wave;  ///< the files to make
  // ct and faces
  double porosity_pct = 7.0;
  std::string pore_shape = "sphere";  ///< sphere | irregular
  int size_px = 0;                    ///< 0: the generator's default (ct 96, faces 256)
  int margin_px = 6, slices = 32, count = 3;
  double pixel_um = 0;                ///< 0: the default (ct 50, faces 10)
  std::vector<double> pore_radius_px; ///< empty, or smallest,largest
  std::optional<double> noise;        ///< gray levels; default per kind
  // compression
  SyntheticCompressionSpec compression;  ///< hold_s, cycles, sample_rate_Hz as given; the rest from below
  double E_GPa = 27.42, strength_MPa = 66.0, upper_stress_MPa = 16.7, lower_stress_MPa = 0.5;
  double cyclic_rate_MPa_s = 0.3, failure_rate_MPa_s = 0.6, gauge_length_mm = 75, side_mm = 150;
  double crosshead_multiplier = 1.0 / 4.5, dropout_time_s = 0;
  int skip_cycle = 0, dropout_channel = 0;
  bool dropout_stuck = false;
  // upv
  double path_mm = 150, t_p_us = 35, t_s_us = 55.1, p_frequency_kHz = 54, s_frequency_kHz = 40;
  double snr_dB = 20, attenuation_dB = 6, bandwidth_factor = 0, delay_us = 0, pretrigger_us = 50;
  double duration_us = 250, dt_us = 0.1, s_precursor = 0;
};

struct SynthesisProducts {
  std::optional<std::pair<std::filesystem::path, std::vector<io::GrayImage>>> stack;  ///< ct: multi-page TIFF
  std::vector<std::pair<std::filesystem::path, io::GrayImage>> images;                 ///< faces: PNG each
  std::vector<std::pair<std::filesystem::path, std::string>> texts;                    ///< CSV records, labelled
  std::string title;                  ///< the truth file's
  std::vector<TruthEntry> entries;    ///< the truth
  nlohmann::ordered_json summary;     ///< kind, seed and the main true values
};

/// The data of `request`. InputError for a missing output path (named by its
/// option), a porosity outside 0.01-60 %, or what the generators refuse.
SynthesisProducts synthesize(const SynthesisRequest& request);

}  // namespace mesowave::lab
