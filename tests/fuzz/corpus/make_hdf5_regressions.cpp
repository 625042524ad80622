// Regression inputs for the HDF5 readers (tests/fuzz/corpus/{signal,packing}_hdf5/crash-*.h5):
// valid files with one attribute or dataset of the wrong shape or type. Not built by CMake; README.md.
#include <cmath>
#include <string>
#include <vector>
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/signal/signal_file.hpp"
using namespace mesowave;
namespace fs = std::filesystem;
static hid_t reopen(const fs::path& p) { return H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT); }
static void doubles_attr(hid_t obj, const char* name, std::vector<double> v) {
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  hsize_t n = v.size();
  hid_t s = H5Screate_simple(1, &n, nullptr);
  hid_t a = H5Acreate2(obj, name, H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, v.data()); H5Aclose(a); H5Sclose(s);
}
static void strings_attr(hid_t obj, const char* name, int n, const char* text) {
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  hid_t t = H5Tcopy(H5T_C_S1); H5Tset_size(t, 8);
  hsize_t dims = hsize_t(n);
  hid_t s = n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &dims, nullptr);
  std::string buf(8 * n, '\0');
  for (int i = 0; i < n; ++i) buf.replace(8 * i, std::string(text).size(), text);
  hid_t a = H5Acreate2(obj, name, t, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, t, buf.data()); H5Aclose(a); H5Sclose(s); H5Tclose(t);
}
int main(int, char** argv) {
  const fs::path c = argv[1];
  std::vector<signal::Signal> sig(1);
  sig[0].name = "B"; sig[0].quantity = "acceleration"; sig[0].unit = "m/s^2"; sig[0].dt_s = 1e-7;
  for (int i = 0; i < 8; ++i) sig[0].samples.push_back(std::sin(0.5 * i));
  auto signal_case = [&](const char* file, auto edit) {
    const fs::path p = c / "signal_hdf5" / file;
    signal::write_signal_file(p, sig);
    hid_t f = reopen(p); hid_t g = H5Gopen2(f, "signals/B", H5P_DEFAULT);
    edit(f, g);
    H5Gclose(g); H5Fclose(f);
  };
  signal_case("crash-dt-array.h5", [](hid_t, hid_t g) { doubles_attr(g, "dt_s", {1e-7, 2e-7, 3e-7, 4e-7, 5e-7, 6e-7, 7e-7, 8e-7}); });
  signal_case("crash-quantity-array.h5", [](hid_t, hid_t g) { strings_attr(g, "quantity", 16, "force"); });
  signal_case("crash-dt-string.h5", [](hid_t, hid_t g) { strings_attr(g, "dt_s", 1, "1e-7"); });
  signal_case("crash-samples-strings.h5", [](hid_t, hid_t g) {
    H5Ldelete(g, "samples", H5P_DEFAULT);
    hid_t t = H5Tcopy(H5T_C_S1); H5Tset_size(t, 4);
    hsize_t n = 3; hid_t s = H5Screate_simple(1, &n, nullptr);
    hid_t d = H5Dcreate2(g, "samples", t, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, "abcdefghijkl"); H5Dclose(d); H5Sclose(s); H5Tclose(t);
  });
  dem::Packing pk;
  pk.centres_m = {{0.001, 0.001, 0.001}}; pk.radii_m = {0.001}; pk.ids = {0};
  pk.container.upper_m = {0.002, 0.002, 0.002};
  auto packing_case = [&](const char* file, auto edit) {
    const fs::path p = c / "packing_hdf5" / file;
    dem::PackingOrigin o; o.numbers = {{"seed", 7}};
    dem::write_packing_file(p, pk, o);
    hid_t f = reopen(p); edit(f); H5Fclose(f);
  };
  packing_case("crash-radius-array.h5", [](hid_t f) { doubles_attr(f, "container_radius_m", {1, 2, 3, 4, 5, 6, 7, 8}); });
  packing_case("crash-shape-array.h5", [](hid_t f) { strings_attr(f, "container_shape", 16, "box"); });
  packing_case("crash-origin-array.h5", [](hid_t f) {
    hid_t g = H5Gopen2(f, "origin", H5P_DEFAULT); doubles_attr(g, "seed", {1, 2, 3, 4, 5, 6, 7, 8}); H5Gclose(g);
  });
  packing_case("crash-density-string.h5", [](hid_t f) { strings_attr(f, "particle_density_kg_m3", 1, "2650"); });
}
