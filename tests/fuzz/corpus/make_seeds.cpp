// The binary seeds of tests/fuzz/corpus (HDF5, PNG, TIFF, WAV) and the CSV/Yade seeds written by
// the library's own writers: small valid files. Not built by CMake; see README.md for the command.
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/dem/packing/packing_import.hpp"
#include "mesowave/io/image.hpp"
#include "mesowave/signal/signal_csv.hpp"
#include "mesowave/signal/signal_file.hpp"
using namespace mesowave;
namespace fs = std::filesystem;
static void put(const fs::path& p, const std::string& s) { fs::create_directories(p.parent_path()); std::ofstream(p, std::ios::binary) << s; }
template <class T> static void le(std::string& s, T v) { char b[sizeof v]; std::memcpy(b, &v, sizeof v); s.append(b, sizeof v); }
static std::string wav(bool f32, int n) {
  std::string data;
  for (int i = 0; i < n; ++i) {
    double x = std::sin(0.3 * i) * std::exp(-0.05 * i);
    if (f32) le<float>(data, float(x)); else le<std::int16_t>(data, std::int16_t(x * 20000));
  }
  std::string s = "RIFF";
  le<std::uint32_t>(s, 4 + 24 + 8 + data.size());
  s += "WAVEfmt ";
  le<std::uint32_t>(s, 16);
  le<std::uint16_t>(s, f32 ? 3 : 1); le<std::uint16_t>(s, 1); le<std::uint32_t>(s, 1000000);
  const std::uint16_t bits = f32 ? 32 : 16;
  le<std::uint32_t>(s, 1000000 * bits / 8); le<std::uint16_t>(s, bits / 8); le<std::uint16_t>(s, bits);
  s += "data"; le<std::uint32_t>(s, data.size()); s += data;
  return s;
}
int main(int, char** argv) {
  const fs::path c = argv[1];
  std::vector<signal::Signal> sig(2);
  for (int k = 0; k < 2; ++k) {
    auto& s = sig[k];
    s.name = k ? "C" : "B"; s.quantity = "acceleration"; s.unit = "m/s^2"; s.component = "z";
    s.t0_s = 0; s.dt_s = 1e-7;
    for (int i = 0; i < 12; ++i) s.samples.push_back(std::sin(0.5 * i + k));
    if (!k) s.position_m = std::array<double, 3>{0.025, 0, 0.05};
  }
  fs::create_directories(c / "signal_hdf5");
  signal::write_signal_file(c / "signal_hdf5/two-signals.h5", sig, {{"scene", "cube-wave"}});
  put(c / "signal_csv/two-signals.csv", signal::signals_to_csv(sig, {{"scene", "cube-wave"}}));
  dem::Packing p;
  p.centres_m = {{0.001, 0.001, 0.001}, {0.003, 0.001, 0.001}, {0.002, 0.0027, 0.001}};
  p.radii_m = {0.001, 0.001, 0.0009};
  p.ids = {0, 1, 2};
  p.container.lower_m = {0, 0, 0}; p.container.upper_m = {0.004, 0.004, 0.002};
  p.particle_density_kg_m3 = 2650;
  fs::create_directories(c / "packing_hdf5");
  dem::write_packing_file(c / "packing_hdf5/three-spheres.h5", p);
  dem::PackingOrigin o; o.text = {{"method", "random"}}; o.numbers = {{"seed", 7}};
  dem::Packing cyl = p; cyl.container.shape = "cylinder"; cyl.container.radius_m = 0.002;
  cyl.container.upper_m = {0.004, 0.004, 0.002};
  dem::write_packing_file(c / "packing_hdf5/cylinder-with-origin.h5", cyl, o);
  put(c / "packing_csv/three-spheres.csv", dem::packing_csv(p));
  put(c / "packing_yade/three-spheres.txt", dem::yade_text(p, " mesowave packing (mw-pack box)"));
  io::GrayImage g; g.width = 6; g.height = 4; g.bit_depth = 8;
  for (int i = 0; i < 24; ++i) g.pixels.push_back(std::uint16_t(i * 10));
  fs::create_directories(c / "image");
  io::write_png_gray(c / "image/gray8.png", g);
  io::GrayImage g16 = g; g16.bit_depth = 16; for (auto& v : g16.pixels) v = std::uint16_t(v * 250);
  io::write_png_gray(c / "image/gray16.png", g16);
  io::RgbImage rgb; rgb.width = 3; rgb.height = 2; rgb.rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30, 40, 50, 60, 70, 80, 90};
  io::write_png_rgb(c / "image/rgb8.png", rgb);
  io::GrayImage g2 = g; for (auto& v : g2.pixels) v = std::uint16_t(255 - v);
  io::write_tiff_gray_stack(c / "image/stack8-2pages.tif", {g, g2});
  io::write_tiff_gray_stack(c / "image/gray16.tif", {g16});
  put(c / "upv_waveform/pcm16.wav", wav(false, 24));
  put(c / "upv_waveform/float32.wav", wav(true, 24));
}
