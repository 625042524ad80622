#pragma once
// The excitation of both papers: an n-cycle sine windowed by a Hann window
// (concrete paper Section 4.1, Fig. 10c; rod paper Section 4), five cycles there.
//   f(t) = A sin(2 pi f_c (t - t_d)) * 0.5 (1 - cos(2 pi f_c (t - t_d) / n))
// for t_d <= t <= t_d + n / f_c, and 0 outside.
#include <cstddef>
#include <vector>

namespace mesowave::signal {

class HannBurst {
public:
  /// `centre_frequency_hz` > 0, `cycles` > 0, `delay_s` >= 0 (InputError otherwise).
  HannBurst(double centre_frequency_hz, double cycles, double amplitude = 1.0, double delay_s = 0.0);

  double operator()(double t_s) const;
  /// Its time derivative (the rate of a force burst: what a velocity receiver records of it in the far field).
  double rate(double t_s) const;
  double duration_s() const { return cycles_ / frequency_; }
  double end_s() const { return delay_ + duration_s(); }
  double centre_frequency_hz() const { return frequency_; }
  double cycles() const { return cycles_; }
  double amplitude() const { return amplitude_; }
  double delay_s() const { return delay_; }

  /// Samples at t_i = t0 + i dt for i < count.
  std::vector<double> sample(double dt_s, std::size_t count, double t0_s = 0.0) const;

private:
  double frequency_, cycles_, amplitude_, delay_;
};

}  // namespace mesowave::signal
