// The rod of the rod paper (191 spheres, R = 5.1 mm, d = 1.03 R, nearest
// neighbours bonded) driven by a Hann burst on the first sphere, checked
// against its modal solution computed here with Eigen:
//  - the same leapfrog recurrence solved mode by mode (diagonalised system):
//    accelerations at the last sphere agree to 1e-9 relative;
//  - the continuous-time modal solution (Duhamel integral in closed form):
//    leapfrog converges to it at second order in dt.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "mesowave/dem/engine/simulation.hpp"
#include "dem/test_packings.hpp"

using namespace mesowave::dem;
using namespace mesowave::dem::testing;

namespace {

constexpr std::size_t kSpheres = 191;
constexpr double kR = 5.1e-3, kSpacing = 1.03 * kR, kDensity = 6044.37, kContactModulus = 6.6e11;
constexpr double kFrequency = 100e3, kCycles = 5, kAmplitude = 1.0;

Scene rod_scene(double dt, double duration) {
  CohesiveFrictionalMaterial m;
  m.E_dem_Pa = kContactModulus;
  m.stiffness_ratio = 0.3;
  m.density_kg_m3 = kDensity;
  m.bond_factor = 1.0;  // nearest neighbours only (the rod paper's d <= L_int < 2d)
  Scene s = bare_scene(m, dt, duration);
  s.actuators.push_back(force_burst("A", end_target(false), "x", kAmplitude, kFrequency, kCycles));
  s.sensors.push_back(motion_sensor("S", end_target(true), MotionQuantity::acceleration, "x"));
  return s;
}

std::vector<double> engine_signal(double dt, double duration) {
  Simulation sim(rod_scene(dt, duration), line_packing(kSpheres, kR, kSpacing, kDensity));
  EXPECT_EQ(sim.choice().model, "chain");
  return sim.run().signals.at(0).samples;
}

struct Modes {
  Eigen::VectorXd lambda;
  Eigen::MatrixXd shape;  // M^-1/2 Q: column j maps modal coordinate j to physical DOFs
  Eigen::VectorXd force_to_mode;  // Q^T M^-1/2 e_0: a unit force on sphere 0 in modal coordinates
};

Modes rod_modes() {
  const double mass = kDensity * 4.0 / 3.0 * std::numbers::pi * kR * kR * kR;
  const double kn = kContactModulus * 2 * kR * kR / (2 * kR);  // Eq. (3)
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(kSpheres, kSpheres);
  for (std::size_t i = 0; i + 1 < kSpheres; ++i) {
    A(i, i) += kn / mass;
    A(i + 1, i + 1) += kn / mass;
    A(i, i + 1) -= kn / mass;
    A(i + 1, i) -= kn / mass;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  Modes m;
  m.lambda = eig.eigenvalues().cwiseMax(0.0);  // the rigid mode is 0 up to round-off
  m.shape = eig.eigenvectors() / std::sqrt(mass);
  m.force_to_mode = eig.eigenvectors().row(0).transpose() / std::sqrt(mass);
  return m;
}

double burst(double t) {
  const double T = kCycles / kFrequency;
  if (t < 0 || t > T) return 0.0;
  const double phase = 2 * std::numbers::pi * kFrequency * t;
  return kAmplitude * std::sin(phase) * 0.5 * (1 - std::cos(phase / kCycles));
}

// Leapfrog, mode by mode: q_{n+1} = q_n + dt p_{n+1/2}, p_{n+1/2} = p_{n-1/2} + dt (g_n - lambda q_n).
std::vector<double> modal_leapfrog(const Modes& m, double dt, std::size_t steps) {
  const std::size_t n = kSpheres;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n), p = Eigen::VectorXd::Zero(n);
  std::vector<double> a_last(steps);
  for (std::size_t s = 0; s < steps; ++s) {
    const Eigen::VectorXd g = m.force_to_mode * burst(double(s) * dt);
    const Eigen::VectorXd modal_acc = g - m.lambda.cwiseProduct(q);
    a_last[s] = m.shape.row(n - 1).dot(modal_acc);
    p += dt * modal_acc;
    q += dt * p;
  }
  return a_last;
}

// int_0^T sin(s tau) sin(b (t - tau)) d tau, b > 0, T <= t.
double duhamel_term(double s, double b, double t, double T) {
  const double plus = (std::sin((s + b) * T - b * t) + std::sin(b * t)) / (s + b);
  const double e = s - b;
  double minus;
  if (std::abs(e * T) < 1e-6) minus = T * std::cos(b * t) - 0.5 * e * T * T * std::sin(b * t);
  else minus = (std::sin(e * T + b * t) - std::sin(b * t)) / e;
  return 0.5 * (plus - minus);
}

// Continuous time: q_j'' + lambda_j q_j = c_j F(t), q(0) = q'(0) = 0.
std::vector<double> modal_continuous(const Modes& m, double dt, std::size_t steps) {
  const double w = 2 * std::numbers::pi * kFrequency;
  const double T_burst = kCycles / kFrequency;
  // F(t) = A [sin(w t)/2 - sin(w+ t)/4 - sin(w- t)/4] inside the burst.
  const double s[3] = {w, w * (1 + 1 / kCycles), w * (1 - 1 / kCycles)};
  const double c[3] = {0.5 * kAmplitude, -0.25 * kAmplitude, -0.25 * kAmplitude};
  std::vector<double> a_last(steps, 0.0);
  for (std::size_t j = 0; j < kSpheres; ++j) {
    const double lambda = m.lambda[j], weight = m.shape(kSpheres - 1, j) * m.force_to_mode[j];
    const double b = std::sqrt(lambda);
    for (std::size_t n = 0; n < steps; ++n) {
      const double t = double(n) * dt;
      double q = 0;
      if (lambda > 1e-6 * m.lambda.maxCoeff()) {
        const double T = std::min(t, T_burst);
        for (int k = 0; k < 3; ++k) q += c[k] * duhamel_term(s[k], b, t, T) / b;
      }
      a_last[n] += weight * (burst(t) - lambda * q);
    }
  }
  return a_last;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

TEST(ChainModal, LeapfrogMatchesTheModalSolutionOfTheSameRecurrence) {
  const double dt = 5e-8, duration = 0.5e-3;
  const auto engine = engine_signal(dt, duration);
  const auto modal = modal_leapfrog(rod_modes(), dt, engine.size());
  ASSERT_EQ(engine.size(), 10000u);
  double diff = 0;
  for (std::size_t i = 0; i < engine.size(); ++i) diff = std::max(diff, std::abs(engine[i] - modal[i]));
  EXPECT_GT(max_abs(modal), 1.0);  // the wave reached the far end (m/s^2 for a 1 N burst)
  EXPECT_LT(diff / max_abs(modal), 1e-9);
}

TEST(ChainModal, ConvergesAtSecondOrderToTheContinuousModalSolution) {
  // First passage: the packet needs ~170 us over the 0.98 m rod, plus the 50 us burst.
  const Modes modes = rod_modes();
  const double duration = 0.25e-3;
  std::vector<double> errors;
  for (double dt : {5e-8, 2.5e-8, 1.25e-8}) {
    const auto engine = engine_signal(dt, duration);
    const auto exact = modal_continuous(modes, dt, engine.size());
    double diff = 0;
    for (std::size_t i = 0; i < engine.size(); ++i) diff = std::max(diff, std::abs(engine[i] - exact[i]));
    errors.push_back(diff / max_abs(exact));
  }
  RecordProperty("relative_error_at_50ns", std::to_string(errors[0]));
  std::printf("max error relative to the peak: dt 50 ns %.3g, 25 ns %.3g, 12.5 ns %.3g; ratios %.3f %.3f\n", errors[0],
              errors[1], errors[2], errors[0] / errors[1], errors[1] / errors[2]);
  EXPECT_NEAR(errors[0] / errors[1], 4.0, 0.4);
  EXPECT_NEAR(errors[1] / errors[2], 4.0, 0.4);
}
