#pragma once
// Discrete Fourier transforms through FFTW, for any length (primes included:
// FFTW uses Rader's algorithm there), with the conventions of numpy.fft:
//   X_k = sum_{j<n} x_j exp(-2 pi i j k / n),   x_j = (1/n) sum_{k<n} X_k exp(+2 pi i j k / n).
//
// Lengths FFTW is slow at (a prime factor above 13: 15-30x slower than a power
// of two near them) take other roads to the same DFT in rfft: a prime N goes
// through Rader's reduction with its real-input symmetry folded in (one cyclic
// and one negacyclic real convolution of length (N-1)/2, by FFTs of a fast
// length >= N-2); any other (29,999 = 131 x 229) through Bluestein's chirp
// convolution, by complex FFTs of a fast length >= 1.5 N. Both cost a few
// fast transforms; their kernels are made once per length and kept.
//
// Plans are made once per (kind, length) and kept for the life of the program;
// making a plan is serialised by a mutex (FFTW's planner is not thread-safe),
// executing one is not (FFTW's new-array execute is), so the transforms may be
// called from several threads at once. Plans are made with FFTW_ESTIMATE: a
// measured plan depends on timings, and with it the rounding of the result -
// mesowave promises the same bits for the same input.
#include <complex>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace mesowave::signal {

using Complex = std::complex<double>;

/// Forward real-to-complex DFT, the n/2 + 1 non-negative frequencies
/// (numpy.fft.rfft(x, n)). `n` = 0 means x.size(); n > x.size() zero pads x.
/// InputError if x is empty (and n is 0) or n < x.size().
std::vector<Complex> rfft(std::span<const double> x, std::size_t n = 0);

/// Inverse of rfft for a record of length `n` (numpy.fft.irfft(X, n)): X holds
/// bins 0..n/2 (InputError otherwise); imaginary parts of bin 0 (and n/2 for
/// even n) are ignored, as the spectrum of a real signal has none.
std::vector<double> irfft(std::span<const Complex> X, std::size_t n);

/// Complex DFT and its inverse (scaled by 1/n), numpy.fft.fft / ifft.
std::vector<Complex> fft(std::span<const Complex> x);
std::vector<Complex> ifft(std::span<const Complex> X);

/// Smallest length >= n of the form 2^a 3^b 5^c 7^d (scipy.fft.next_fast_len).
std::size_t fast_fft_length(std::size_t n);

/// Largest prime factor of n (n for a prime, 1 for n <= 1).
std::size_t largest_prime_factor(std::size_t n);

/// Whether FFTW is slow at length n: a prime factor above 13 (FFTW has no
/// codelet for it) in a record long enough for it to matter (n >= 256).
bool slow_fft_length(std::size_t n);

/// Zero padding before a transform. Padding moves the circular wrap-around of
/// the FFT away from the record (the Hilbert transform of a burst near one end
/// otherwise leaks into the other end) and interpolates a spectrum more finely;
/// it adds no information.
struct Padding {
  enum class Mode {
    none,            ///< transform the record as it is (scipy.signal.hilbert(x))
    double_length,   ///< at least 2 n, rounded up to a fast length
    power_of_two,    ///< the next power of two >= n
    to_length,       ///< exactly `length` (>= n)
  };
  Mode mode = Mode::none;
  std::size_t length = 0;  ///< for to_length

  /// The FFT length for a record of n samples; InputError if to_length < n.
  std::size_t fft_length(std::size_t n) const;
  /// "none", "double", "pow2" or the length, as `parse` reads it.
  std::string name() const;
  /// Reads "none", "double", "pow2" or a length ("65536"); InputError otherwise.
  static Padding parse(std::string_view text);
};

/// FFTW-aligned storage: every transform runs on such buffers, so a plan
/// always executes the SIMD code path it was made for.
template <class T>
class FftBuffer {
public:
  FftBuffer() = default;
  explicit FftBuffer(std::size_t n);
  FftBuffer(FftBuffer&& other) noexcept : data_(other.data_), size_(other.size_) { other.data_ = nullptr, other.size_ = 0; }
  FftBuffer& operator=(FftBuffer&& other) noexcept;
  FftBuffer(const FftBuffer&) = delete;
  FftBuffer& operator=(const FftBuffer&) = delete;
  ~FftBuffer();
  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

/// A per-thread FFTW-aligned work buffer of at least n elements, reused by
/// later calls on the same thread: on virtual machines a fresh page costs
/// more than transforming it, so the transforms allocate nothing in steady
/// state. `slot` (0..15) names the buffer; nested users take different slots
/// (fft.cpp 0-3 and 14-15, envelope 4-7, spectrum 8-9, correlation 10-13).
/// Buffers over 64 MiB are released when the lease ends.
template <class T>
class ScratchBuffer {
public:
  ScratchBuffer(int slot, std::size_t n);
  ~ScratchBuffer();
  ScratchBuffer(const ScratchBuffer&) = delete;
  ScratchBuffer& operator=(const ScratchBuffer&) = delete;
  T* data() { return data_; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }

private:
  int slot_;
  T* data_;
  std::size_t size_;
};

/// The unscaled transforms on FFTW-aligned storage (FftBuffer, ScratchBuffer),
/// for code that chains them: `out` gets bins 0..n/2 of the record `in`.
void rfft_unscaled(const double* in, Complex* out, std::size_t n);
/// Complex-to-real transform of length n (n times the record); `in` (bins
/// 0..n/2) is overwritten.
void irfft_unscaled(Complex* in, double* out, std::size_t n);

/// The same on FftBuffers: in.size() = n, out.size() = n/2 + 1.
void rfft_into(const FftBuffer<double>& in, FftBuffer<Complex>& out);
void irfft_unscaled_into(FftBuffer<Complex>& in, FftBuffer<double>& out);

}  // namespace mesowave::signal
