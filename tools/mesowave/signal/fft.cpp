#include "mesowave/signal/fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <charconv>
#include <limits>
#include <map>
#include <mutex>
#include <new>
#include <stdexcept>
#include <utility>

#include "mesowave/core/error.hpp"

namespace mesowave::signal {
namespace {

enum class Kind { r2c, c2r, c2c_forward, c2c_backward };

fftw_complex* as_fftw(Complex* p) { return reinterpret_cast<fftw_complex*>(p); }

// One plan per (kind, length), made on first use and kept: FFTW_ESTIMATE
// chooses by heuristics only, so the same length gets the same plan (and the
// same rounding) in every run.
fftw_plan cached_plan(Kind kind, std::size_t n) {
  static std::mutex mutex;
  static auto* plans = new std::map<std::pair<Kind, std::size_t>, fftw_plan>();  // never freed: outlives callers
  std::lock_guard lock(mutex);
  auto it = plans->find({kind, n});
  if (it != plans->end()) return it->second;
  if (n > std::size_t(std::numeric_limits<int>::max())) throw InputError("FFT length " + std::to_string(n) + " is too large");
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

std::vector<Complex> complex_transform(std::span<const Complex> x, Kind kind) {
  require_length(x.size(), kind == Kind::c2c_forward ? "fft" : "ifft");
  const std::size_t n = x.size();
  FftBuffer<Complex> in(n), out(n);
  std::copy(x.begin(), x.end(), in.begin());
  fftw_execute_dft(cached_plan(kind, n), as_fftw(in.data()), as_fftw(out.data()));
  std::vector<Complex> result(out.begin(), out.end());
  if (kind == Kind::c2c_backward)
    for (auto& v : result) v /= double(n);
  return result;
}

bool is_fast(std::size_t n) {
  for (std::size_t p : {2, 3, 5, 7})
    while (n % p == 0) n /= p;
  return n == 1;
}

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

// ---- transforms ---------------------------------------------------------------

void rfft_into(const FftBuffer<double>& in, FftBuffer<Complex>& out) {
  const std::size_t n = in.size();
  require_length(n, "rfft");
  if (out.size() != n / 2 + 1) throw std::logic_error("rfft_into: output must hold n/2 + 1 bins");
  // An out-of-place r2c transform leaves its input as it was.
  fftw_execute_dft_r2c(cached_plan(Kind::r2c, n), const_cast<double*>(in.data()), as_fftw(out.data()));
}

void irfft_unscaled_into(FftBuffer<Complex>& in, FftBuffer<double>& out) {
  const std::size_t n = out.size();
  require_length(n, "irfft");
  if (in.size() != n / 2 + 1) throw std::logic_error("irfft_unscaled_into: input must hold n/2 + 1 bins");
  in[0].imag(0.0);
  if (n % 2 == 0) in[n / 2].imag(0.0);
  fftw_execute_dft_c2r(cached_plan(Kind::c2r, n), as_fftw(in.data()), out.data());
}

std::vector<Complex> rfft(std::span<const double> x, std::size_t n) {
  if (n == 0) n = x.size();
  require_length(n, "rfft");
  if (n < x.size())
    throw InputError("rfft: FFT length " + std::to_string(n) + " is shorter than the record (" +
                     std::to_string(x.size()) + " samples)");
  FftBuffer<double> in(n);
  std::copy(x.begin(), x.end(), in.begin());
  std::fill(in.begin() + x.size(), in.end(), 0.0);
  FftBuffer<Complex> out(n / 2 + 1);
  rfft_into(in, out);
  return {out.begin(), out.end()};
}

std::vector<double> irfft(std::span<const Complex> X, std::size_t n) {
  require_length(n, "irfft");
  if (X.size() != n / 2 + 1)
    throw InputError("irfft: a record of " + std::to_string(n) + " samples needs " + std::to_string(n / 2 + 1) +
                     " bins, got " + std::to_string(X.size()));
  FftBuffer<Complex> in(X.size());
  std::copy(X.begin(), X.end(), in.begin());
  FftBuffer<double> out(n);
  irfft_unscaled_into(in, out);
  std::vector<double> result(out.begin(), out.end());
  for (auto& v : result) v /= double(n);
  return result;
}

std::vector<Complex> fft(std::span<const Complex> x) { return complex_transform(x, Kind::c2c_forward); }
std::vector<Complex> ifft(std::span<const Complex> X) { return complex_transform(X, Kind::c2c_backward); }

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
