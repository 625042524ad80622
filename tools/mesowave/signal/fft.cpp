#include "mesowave/signal/fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>

#include "mesowave/core/error.hpp"
#include "mesowave/signal/unit_root.hpp"

namespace mesowave::signal {
namespace {

enum class Kind { r2c, c2r, c2c_forward, c2c_backward };

fftw_complex* as_fftw(Complex* p) { return reinterpret_cast<fftw_complex*>(p); }

// Scratch slots of this file (see ScratchBuffer).
constexpr int slot_a = 0, slot_b = 1, slot_c = 2, slot_d = 3, slot_api_in = 14, slot_api_out = 15;

// One plan per (kind, length), made on first use and kept: FFTW_ESTIMATE
// chooses by heuristics only, so the same length gets the same plan (and the
// same rounding) in every run.
fftw_plan cached_plan(Kind kind, std::size_t n) {
  static std::mutex mutex;
  static auto* plans = new std::map<std::pair<Kind, std::size_t>, fftw_plan>();  // never freed: outlives callers
  std::lock_guard lock(mutex);
  auto it = plans->find({kind, n});
  if (it != plans->end()) return it->second;
  if (n > std::size_t(std::numeric_limits<int>::max()))
    throw InputError("FFT length " + std::to_string(n) + " is too large");
  const int len = int(n);
  const unsigned flags = FFTW_ESTIMATE;
  fftw_plan plan = nullptr;
  switch (kind) {
    case Kind::r2c: {
      FftBuffer<double> in(n);
      FftBuffer<Complex> out(n / 2 + 1);
      plan = fftw_plan_dft_r2c_1d(len, in.data(), as_fftw(out.data()), flags);
      break;
    }
    case Kind::c2r: {
      FftBuffer<Complex> in(n / 2 + 1);
      FftBuffer<double> out(n);
      plan = fftw_plan_dft_c2r_1d(len, as_fftw(in.data()), out.data(), flags);
      break;
    }
    case Kind::c2c_forward:
    case Kind::c2c_backward: {
      FftBuffer<Complex> in(n), out(n);
      plan = fftw_plan_dft_1d(len, as_fftw(in.data()), as_fftw(out.data()),
                              kind == Kind::c2c_forward ? FFTW_FORWARD : FFTW_BACKWARD, flags);
      break;
    }
  }
  if (!plan) throw std::runtime_error("FFTW could not plan a transform of length " + std::to_string(n));
  plans->emplace(std::pair{kind, n}, plan);
  return plan;
}

void require_length(std::size_t n, const char* what) {
  if (n == 0) throw InputError(std::string(what) + ": cannot transform an empty record");
}

bool is_fast(std::size_t n) {
  for (std::size_t p : {2, 3, 5, 7})
    while (n % p == 0) n /= p;
  return n == 1;
}

bool is_prime(std::size_t n) {
  if (n < 2) return false;
  for (std::size_t p = 2; p * p <= n; ++p)
    if (n % p == 0) return false;
  return true;
}

// A kernel made once per length and kept, its construction outside the lock
// (it may plan transforms); the first one stored wins.
template <class Plan>
const Plan& cached(std::size_t n, const std::function<std::unique_ptr<Plan>(std::size_t)>& make) {
  static std::mutex mutex;
  static auto* plans = new std::map<std::size_t, std::unique_ptr<Plan>>();
  {
    std::lock_guard lock(mutex);
    if (auto it = plans->find(n); it != plans->end()) return *it->second;
  }
  auto plan = make(n);
  std::lock_guard lock(mutex);
  return *plans->emplace(n, std::move(plan)).first->second;
}

// ---- Rader's algorithm for real input of prime length -----------------------
//
// With g a primitive root mod N, M = N - 1 = 2K and w = exp(-2 pi i / N),
//   X_0 = sum x_j,   X_{g^-m} = x_0 + sum_{q<M} u_q v_{q-m},   u_q = x_{g^q},  v_p = w^{g^p},
// a cyclic correlation of length M (Rader 1968). Since g^K = -1 (mod N),
// v_{p+K} = conj(v_p): Re v has period K and Im v changes sign after K, so
//   Re c_m = sum_{q<K} (u_q + u_{q+K}) Re v_{(q-m) mod K}                  (cyclic, length K)
//   Im c_m = sum_{q<K} (u_q - u_{q+K}) Im v_{q-m},  Im v_{-p} = -Im v_{K-p}  (negacyclic, length K)
// and m < K gives one of each conjugate pair X_k, X_{N-k}: all a real input
// needs. Each correlation is a linear convolution with a kernel over the
// offsets -(K-1)..K-1, exact in an FFT of length L >= 2K - 1 = N - 2.
struct RaderPlan {
  std::size_t n = 0, half = 0, fft_length = 0;
  std::vector<std::uint32_t> power;       // g^q mod n, q < n - 1
  FftBuffer<Complex> cyclic, negacyclic;  // kernel spectra, scaled by 1/L
};

std::uint64_t power_mod(std::uint64_t base, std::uint64_t exp, std::uint64_t mod) {
  std::uint64_t result = 1;
  base %= mod;
  for (; exp; exp >>= 1, base = base * base % mod)
    if (exp & 1) result = result * base % mod;
  return result;
}

std::uint64_t primitive_root(std::uint64_t n) {
  std::vector<std::uint64_t> factors;
  std::uint64_t m = n - 1;
  for (std::uint64_t p = 2; p * p <= m; ++p)
    if (m % p == 0) {
      factors.push_back(p);
      while (m % p == 0) m /= p;
    }
  if (m > 1) factors.push_back(m);
  for (std::uint64_t g = 2;; ++g) {
    bool root = true;
    for (auto p : factors) root = root && power_mod(g, (n - 1) / p, n) != 1;
    if (root) return g;
  }
}

// r2c of a real kernel k(d), d = -(K-1)..K-1, stored at t = K-1-d: the
// convolution sum_q a_q k(q - m) then sits at index m + K - 1.
FftBuffer<Complex> kernel_spectrum(std::size_t half, std::size_t fft_length, const std::function<double(long)>& kernel) {
  FftBuffer<double> g(fft_length);
  std::fill(g.begin(), g.end(), 0.0);
  for (std::size_t t = 0; t + 1 < 2 * half; ++t) g[t] = kernel(long(half) - 1 - long(t)) / double(fft_length);
  FftBuffer<Complex> spectrum(fft_length / 2 + 1);
  fftw_execute_dft_r2c(cached_plan(Kind::r2c, fft_length), g.data(), as_fftw(spectrum.data()));
  return spectrum;
}

std::unique_ptr<RaderPlan> make_rader_plan(std::size_t n) {
  auto plan = std::make_unique<RaderPlan>();
  plan->n = n;
  plan->half = (n - 1) / 2;
  plan->fft_length = fast_fft_length(2 * plan->half - 1);
  const std::uint64_t g = primitive_root(n);
  plan->power.resize(n - 1);
  std::uint64_t p = 1;
  for (auto& v : plan->power) v = std::uint32_t(p), p = p * g % n;
  const auto& power = plan->power;
  const long half = long(plan->half);
  // Re v_p = cos(2 pi g^p / N), Im v_p = -sin(2 pi g^p / N).
  auto re = [&](long d) { return unit_root(power[std::size_t((d % half + half) % half)], n).real(); };
  auto im = [&](long d) {
    return d >= 0 ? -unit_root(power[std::size_t(d)], n).imag() : unit_root(power[std::size_t(d + half)], n).imag();
  };
  plan->cyclic = kernel_spectrum(plan->half, plan->fft_length, re);
  plan->negacyclic = kernel_spectrum(plan->half, plan->fft_length, im);
  return plan;
}

void rader_rfft(const double* x, Complex* out, const RaderPlan& plan) {
  const std::size_t n = plan.n, K = plan.half, L = plan.fft_length, M = n - 1;
  ScratchBuffer<double> a(slot_a, L), b(slot_b, L);
  ScratchBuffer<Complex> A(slot_c, L / 2 + 1), B(slot_d, L / 2 + 1);
  for (std::size_t q = 0; q < K; ++q) {
    const double lo = x[plan.power[q]], hi = x[plan.power[q + K]];
    a[q] = lo + hi;
    b[q] = lo - hi;
  }
  std::fill(a.begin() + K, a.begin() + L, 0.0);
  std::fill(b.begin() + K, b.begin() + L, 0.0);
  const fftw_plan forward = cached_plan(Kind::r2c, L), inverse = cached_plan(Kind::c2r, L);
  fftw_execute_dft_r2c(forward, a.data(), as_fftw(A.data()));
  fftw_execute_dft_r2c(forward, b.data(), as_fftw(B.data()));
  for (std::size_t k = 0; k <= L / 2; ++k) {
    A[k] *= plan.cyclic[k];
    B[k] *= plan.negacyclic[k];
  }
  fftw_execute_dft_c2r(inverse, as_fftw(A.data()), a.data());
  fftw_execute_dft_c2r(inverse, as_fftw(B.data()), b.data());
  double sum = 0;
  for (std::size_t j = 0; j < n; ++j) sum += x[j];
  out[0] = sum;
  for (std::size_t m = 0; m < K; ++m) {
    const std::size_t k = plan.power[(M - m) % M];  // g^-m
    const Complex X(x[0] + a[m + K - 1], b[m + K - 1]);
    if (2 * k < n) out[k] = X;
    else out[n - k] = std::conj(X);
  }
}

// ---- Bluestein's algorithm for real input of any length ----------------------
//
// jk = (j^2 + k^2 - (k-j)^2)/2 turns the DFT into a convolution with the chirp
// c_m = exp(i pi m^2 / N):  X_k = conj(c_k) sum_j (x_j conj(c_j)) c_{k-j}  (Bluestein 1970).
// A real input needs k <= H = N/2 only, so the kernel spans the offsets
// -(N-1)..H and an FFT of length L >= N + H holds the convolution exactly.
struct BluesteinPlan {
  std::size_t n = 0, fft_length = 0;
  std::vector<Complex> chirp;  // c_j, j < N
  FftBuffer<Complex> kernel;   // FFT of c over the offsets, scaled by 1/L
};

std::unique_ptr<BluesteinPlan> make_bluestein_plan(std::size_t n) {
  auto plan = std::make_unique<BluesteinPlan>();
  plan->n = n;
  const std::size_t H = n / 2, L = fast_fft_length(n + H);
  plan->fft_length = L;
  // exp(i pi m^2 / N), the phase reduced exactly: m^2 mod 2N.
  auto chirp = [n](std::uint64_t m) { return unit_root((m % (2 * n)) * (m % (2 * n)) % (2 * n), 2 * n); };
  plan->chirp.resize(n);
  for (std::size_t j = 0; j < n; ++j) plan->chirp[j] = chirp(j);
  FftBuffer<Complex> g(L);
  plan->kernel = FftBuffer<Complex>(L);
  std::fill(g.begin(), g.end(), Complex(0.0));
  for (std::size_t t = 0; t < n + H; ++t) {  // g_t = c_{t-(N-1)}; c is even in its index
    const long d = long(t) - long(n - 1);
    g[t] = chirp(std::uint64_t(d < 0 ? -d : d)) / double(L);
  }
  fftw_execute_dft(cached_plan(Kind::c2c_forward, L), as_fftw(g.data()), as_fftw(plan->kernel.data()));
  return plan;
}

void bluestein_rfft(const double* x, Complex* out, const BluesteinPlan& plan) {
  const std::size_t n = plan.n, L = plan.fft_length, H = n / 2;
  ScratchBuffer<Complex> a(slot_a, L), A(slot_b, L);
  for (std::size_t j = 0; j < n; ++j) a[j] = x[j] * std::conj(plan.chirp[j]);
  std::fill(a.begin() + n, a.begin() + L, Complex(0.0));
  fftw_execute_dft(cached_plan(Kind::c2c_forward, L), as_fftw(a.data()), as_fftw(A.data()));
  for (std::size_t k = 0; k < L; ++k) A[k] *= plan.kernel[k];
  fftw_execute_dft(cached_plan(Kind::c2c_backward, L), as_fftw(A.data()), as_fftw(a.data()));
  for (std::size_t k = 0; k <= H; ++k) out[k] = std::conj(plan.chirp[k]) * a[k + n - 1];
}

std::vector<Complex> complex_transform(std::span<const Complex> x, Kind kind) {
  require_length(x.size(), kind == Kind::c2c_forward ? "fft" : "ifft");
  const std::size_t n = x.size();
  ScratchBuffer<Complex> in(slot_api_in, n), out(slot_api_out, n);
  std::copy(x.begin(), x.end(), in.begin());
  fftw_execute_dft(cached_plan(kind, n), as_fftw(in.data()), as_fftw(out.data()));
  std::vector<Complex> result(out.begin(), out.begin() + n);
  if (kind == Kind::c2c_backward)
    for (auto& v : result) v /= double(n);
  return result;
}

// Per-thread scratch storage, freed when the thread ends.
struct ScratchCache {
  std::array<void*, 16> data{};
  std::array<std::size_t, 16> bytes{};
  std::array<bool, 16> leased{};
  ~ScratchCache() {
    for (void* p : data)
      if (p) fftw_free(p);
  }
};
thread_local ScratchCache scratch_cache;
constexpr std::size_t keep_bytes = std::size_t(64) << 20;

}  // namespace

// ---- buffers ----------------------------------------------------------------

template <class T>
FftBuffer<T>::FftBuffer(std::size_t n) : size_(n) {
  if (n == 0) return;
  data_ = static_cast<T*>(fftw_malloc(n * sizeof(T)));
  if (!data_) throw std::bad_alloc();
}

template <class T>
FftBuffer<T>& FftBuffer<T>::operator=(FftBuffer&& other) noexcept {
  if (this != &other) {
    if (data_) fftw_free(data_);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

template <class T>
FftBuffer<T>::~FftBuffer() {
  if (data_) fftw_free(data_);
}

template class FftBuffer<double>;
template class FftBuffer<Complex>;

template <class T>
ScratchBuffer<T>::ScratchBuffer(int slot, std::size_t n) : slot_(slot), size_(n) {
  if (slot < 0 || slot >= 16) throw std::logic_error("scratch slot out of range");
  auto& c = scratch_cache;
  if (c.leased[std::size_t(slot)]) throw std::logic_error("scratch slot " + std::to_string(slot) + " is in use");
  const std::size_t bytes = std::max<std::size_t>(n, 1) * sizeof(T);
  if (c.bytes[std::size_t(slot)] < bytes) {
    if (c.data[std::size_t(slot)]) fftw_free(c.data[std::size_t(slot)]);
    c.data[std::size_t(slot)] = nullptr;
    c.bytes[std::size_t(slot)] = 0;
    void* p = fftw_malloc(bytes);
    if (!p) throw std::bad_alloc();
    c.data[std::size_t(slot)] = p;
    c.bytes[std::size_t(slot)] = bytes;
  }
  c.leased[std::size_t(slot)] = true;
  data_ = static_cast<T*>(c.data[std::size_t(slot)]);
}

template <class T>
ScratchBuffer<T>::~ScratchBuffer() {
  auto& c = scratch_cache;
  c.leased[std::size_t(slot_)] = false;
  if (c.bytes[std::size_t(slot_)] > keep_bytes) {
    fftw_free(c.data[std::size_t(slot_)]);
    c.data[std::size_t(slot_)] = nullptr;
    c.bytes[std::size_t(slot_)] = 0;
  }
}

template class ScratchBuffer<double>;
template class ScratchBuffer<Complex>;

// ---- transforms ---------------------------------------------------------------

void rfft_unscaled(const double* in, Complex* out, std::size_t n) {
  require_length(n, "rfft");
  if (slow_fft_length(n)) {
    if (is_prime(n)) return rader_rfft(in, out, cached<RaderPlan>(n, make_rader_plan));
    return bluestein_rfft(in, out, cached<BluesteinPlan>(n, make_bluestein_plan));
  }
  // An out-of-place r2c transform leaves its input as it was.
  fftw_execute_dft_r2c(cached_plan(Kind::r2c, n), const_cast<double*>(in), as_fftw(out));
}

void irfft_unscaled(Complex* in, double* out, std::size_t n) {
  require_length(n, "irfft");
  in[0].imag(0.0);
  if (n % 2 == 0) in[n / 2].imag(0.0);
  fftw_execute_dft_c2r(cached_plan(Kind::c2r, n), as_fftw(in), out);
}

void rfft_into(const FftBuffer<double>& in, FftBuffer<Complex>& out) {
  if (out.size() != in.size() / 2 + 1) throw std::logic_error("rfft_into: output must hold n/2 + 1 bins");
  rfft_unscaled(in.data(), out.data(), in.size());
}

void irfft_unscaled_into(FftBuffer<Complex>& in, FftBuffer<double>& out) {
  if (in.size() != out.size() / 2 + 1) throw std::logic_error("irfft_unscaled_into: input must hold n/2 + 1 bins");
  irfft_unscaled(in.data(), out.data(), out.size());
}

std::vector<Complex> rfft(std::span<const double> x, std::size_t n) {
  if (n == 0) n = x.size();
  require_length(n, "rfft");
  if (n < x.size())
    throw InputError("rfft: FFT length " + std::to_string(n) + " is shorter than the record (" +
                     std::to_string(x.size()) + " samples)");
  ScratchBuffer<double> in(slot_api_in, n);
  std::copy(x.begin(), x.end(), in.begin());
  std::fill(in.begin() + x.size(), in.begin() + n, 0.0);
  ScratchBuffer<Complex> out(slot_api_out, n / 2 + 1);
  rfft_unscaled(in.data(), out.data(), n);
  return {out.begin(), out.begin() + n / 2 + 1};
}

std::vector<double> irfft(std::span<const Complex> X, std::size_t n) {
  require_length(n, "irfft");
  if (X.size() != n / 2 + 1)
    throw InputError("irfft: a record of " + std::to_string(n) + " samples needs " + std::to_string(n / 2 + 1) +
                     " bins, got " + std::to_string(X.size()));
  ScratchBuffer<Complex> in(slot_api_in, X.size());
  std::copy(X.begin(), X.end(), in.begin());
  ScratchBuffer<double> out(slot_api_out, n);
  irfft_unscaled(in.data(), out.data(), n);
  std::vector<double> result(out.begin(), out.begin() + n);
  for (auto& v : result) v /= double(n);
  return result;
}

std::vector<Complex> fft(std::span<const Complex> x) { return complex_transform(x, Kind::c2c_forward); }
std::vector<Complex> ifft(std::span<const Complex> X) { return complex_transform(X, Kind::c2c_backward); }

std::size_t largest_prime_factor(std::size_t n) {
  std::size_t largest = 1;
  for (std::size_t p = 2; p * p <= n; ++p)
    while (n % p == 0) largest = p, n /= p;
  return n > 1 ? n : largest;
}

bool slow_fft_length(std::size_t n) { return n >= 256 && largest_prime_factor(n) > 13; }

std::size_t fast_fft_length(std::size_t n) {
  if (n <= 1) return 1;
  while (!is_fast(n)) ++n;
  return n;
}

// ---- padding ----------------------------------------------------------------

std::size_t Padding::fft_length(std::size_t n) const {
  switch (mode) {
    case Mode::none: return n;
    case Mode::double_length: return fast_fft_length(2 * n);
    case Mode::power_of_two: {
      std::size_t m = 1;
      while (m < n) m *= 2;
      return m;
    }
    case Mode::to_length:
      if (length < n)
        throw InputError("padding length " + std::to_string(length) + " is shorter than the record (" +
                         std::to_string(n) + " samples)");
      return length;
  }
  return n;
}

std::string Padding::name() const {
  switch (mode) {
    case Mode::none: return "none";
    case Mode::double_length: return "double";
    case Mode::power_of_two: return "pow2";
    case Mode::to_length: return std::to_string(length);
  }
  return "none";
}

Padding Padding::parse(std::string_view text) {
  if (text == "none") return {};
  if (text == "double") return {Mode::double_length, 0};
  if (text == "pow2") return {Mode::power_of_two, 0};
  std::size_t length = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), length);
  if (ec != std::errc() || ptr != text.data() + text.size() || length == 0)
    throw InputError("padding '" + std::string(text) +
                     "' must be none, double (>= 2n, fast length), pow2 (next power of two) or an FFT length");
  return {Mode::to_length, length};
}

}  // namespace mesowave::signal
