#include "mesowave/fem/solver.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <stdexcept>

#include "mesowave/core/check.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/fem/box_operator.hpp"

namespace mesowave::fem {

namespace {

// Element forces f_e = K_e u_e for elements [begin, end) of one colour, added to f.
// Column-wise axpy over the symmetric K_e (no reduction to reorder), compiled
// for AVX-512, AVX2 and baseline; the clone is chosen once per machine, so the
// bits do not depend on the thread count. kGroup elements at a time: each one's
// f_e is summed over the columns in order, as alone (the same bits), but the
// group's sums are independent chains of additions, which the core overlaps -
// one element's 24 dependent additions per row left it waiting on their latency.
// The elements of a colour share no node, so their scatters commute.
constexpr int kGroup = 4;

template <int NPE, int DIM, int G>
[[gnu::always_inline]] inline void element_group(const std::int32_t* __restrict elems, std::size_t first,
                                                 const std::int32_t* __restrict conn, const std::int32_t* __restrict types,
                                                 const double* __restrict K, const double* __restrict u, double* __restrict f) {
  constexpr int N = NPE * DIM;
  const std::int32_t* nd[G];
  const double* Ke[G];
  double ue[G][N], fe[G][N];
  for (int g = 0; g < G; ++g) {
    const std::int32_t e = elems[first + std::size_t(g)];
    nd[g] = conn + std::size_t(e) * NPE;
    Ke[g] = K + std::size_t(types[e]) * N * N;
    for (int a = 0; a < NPE; ++a)
      for (int d = 0; d < DIM; ++d) ue[g][a * DIM + d] = u[std::size_t(nd[g][a]) * DIM + d];
    for (int r = 0; r < N; ++r) fe[g][r] = 0;
  }
  for (int c = 0; c < N; ++c)
#pragma GCC unroll 4
    for (int g = 0; g < G; ++g) {
      const double uc = ue[g][c];
      const double* col = Ke[g] + std::size_t(c) * N;
      for (int r = 0; r < N; ++r) fe[g][r] += col[r] * uc;
    }
  for (int g = 0; g < G; ++g)
    for (int a = 0; a < NPE; ++a)
      for (int d = 0; d < DIM; ++d) f[std::size_t(nd[g][a]) * DIM + d] += fe[g][a * DIM + d];
}

template <int NPE, int DIM>
[[gnu::always_inline]] inline void element_forces(const std::int32_t* __restrict elems, std::size_t begin, std::size_t end,
                           const std::int32_t* __restrict conn, const std::int32_t* __restrict types,
                           const double* __restrict K, const double* __restrict u, double* __restrict f) {
  std::size_t i = begin;
  for (; i + kGroup <= end; i += kGroup) element_group<NPE, DIM, kGroup>(elems, i, conn, types, K, u, f);
  for (; i < end; ++i) element_group<NPE, DIM, 1>(elems, i, conn, types, K, u, f);
}

__attribute__((target_clones("avx512f", "avx2", "default"))) void hex8_forces(
    const std::int32_t* elems, std::size_t begin, std::size_t end, const std::int32_t* conn, const std::int32_t* types,
    const double* K, const double* u, double* f) {
  element_forces<8, 3>(elems, begin, end, conn, types, K, u, f);
}

__attribute__((target_clones("avx512f", "avx2", "default"))) void quad4_forces(
    const std::int32_t* elems, std::size_t begin, std::size_t end, const std::int32_t* conn, const std::int32_t* types,
    const double* K, const double* u, double* f) {
  element_forces<4, 2>(elems, begin, end, conn, types, K, u, f);
}

// The stiffness matrices of all types side by side, and the kernel for the element kind; on a box,
// the Kronecker form (box_operator.hpp) and a workspace per thread.
struct Assembler {
  const FemModel& model;
  std::vector<double> K;
  std::optional<BoxOperator> box;
  mutable std::vector<BoxOperator::Workspace> work;

  explicit Assembler(const FemModel& m) : model(m) {
    if (m.box.valid()) {
      box.emplace(m.box, m.material);
      work.resize(std::size_t(omp_get_max_threads()));
    } else {
      for (const auto& k : m.stiffness) K.insert(K.end(), k.begin(), k.end());
    }
  }

  // Inside a parallel region, f zero on entry: f = K u, colour by colour (barrier after each), or
  // on a box node plane by node plane (each thread its planes: the same bits for any count).
  void add(const double* u, double* f) const {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    if (box) {
      const std::int64_t planes = box->planes();
      box->apply(u, f, planes * t / nt, planes * (t + 1) / nt, work[std::size_t(t)]);
#pragma omp barrier
      return;
    }
    for (const auto& colour : model.colours) {
      const std::size_t n = colour.size();
      const std::size_t b = n * std::size_t(t) / std::size_t(nt), e = n * std::size_t(t + 1) / std::size_t(nt);
      if (model.dim == 3)
        hex8_forces(colour.data(), b, e, model.connectivity.data(), model.element_type.data(), K.data(), u, f);
      else
        quad4_forces(colour.data(), b, e, model.connectivity.data(), model.element_type.data(), K.data(), u, f);
#pragma omp barrier
    }
  }
};

// Static split of [0, n) for the calling thread.
std::pair<std::size_t, std::size_t> my_range(std::size_t n) {
  const int nt = omp_get_num_threads(), t = omp_get_thread_num();
  return {n * std::size_t(t) / std::size_t(nt), n * std::size_t(t + 1) / std::size_t(nt)};
}

// f = K u (f overwritten), using the element colouring: the power iteration's product.
void apply_stiffness(const FemModel& model, const std::vector<double>& u, std::vector<double>& f) {
  f.assign(model.dof_count(), 0.0);
  const Assembler A(model);
#pragma omp parallel num_threads(region_threads(model.element_count(), 4000))
  A.add(u.data(), f.data());
}

}  // namespace

double global_max_omega(const FemModel& model, int iterations) {
  const std::size_t n = model.dof_count();
  const auto dim = std::size_t(model.dim);
  std::vector<double> x(n), f;
  // Start from a checkerboard-like pattern, rich in the highest modes.
  for (std::size_t i = 0; i < n; ++i) x[i] = model.fixed[i] ? 0.0 : ((i * 2654435761u) % 1000) / 500.0 - 1.0;
  double lambda = 0;
  for (int it = 0; it < iterations; ++it) {
    // Symmetric form: y = M^-1/2 K M^-1/2 x.
    std::vector<double> z(n);
    for (std::size_t i = 0; i < n; ++i) z[i] = x[i] / std::sqrt(model.mass[i / dim]);
    apply_stiffness(model, z, f);
    double norm = 0, dot = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double y = model.fixed[i] ? 0.0 : f[i] / std::sqrt(model.mass[i / dim]);
      dot += y * x[i];
      f[i] = y;
    }
    double xx = 0;
    for (std::size_t i = 0; i < n; ++i) xx += x[i] * x[i];
    lambda = dot / xx;
    for (std::size_t i = 0; i < n; ++i) norm += f[i] * f[i];
    norm = std::sqrt(norm);
    if (norm == 0) break;
    for (std::size_t i = 0; i < n; ++i) x[i] = f[i] / norm;
  }
  return std::sqrt(std::max(0.0, lambda));
}

ExplicitResult run_explicit(const FemModel& model, const BurstLoad& load, const std::vector<Probe>& probes,
                            const ExplicitOptions& opt, const SpaceTimeRequest* st) {
  require_positive("time step", opt.dt_s, "s");
  if (opt.steps < 1) throw InputError("number of steps (" + std::to_string(opt.steps) + ") must be at least 1");
  if (opt.sample_stride < 1) throw InputError("sample stride must be at least 1");
  if (!std::isfinite(opt.alpha_damping_per_s) || opt.alpha_damping_per_s < 0)
    throw InputError("damping alpha (" + format_number(opt.alpha_damping_per_s) + " 1/s) must be finite and >= 0");
  const double dt_stable = model.stable_dt();
  if (opt.dt_s > dt_stable && !opt.allow_unstable)
    throw InputError("time step (" + format_quantity(opt.dt_s * 1e6, "us") + ") exceeds the stable step (" +
                     format_quantity(dt_stable * 1e6, "us") + ") of this mesh");
  const std::size_t ndof = model.dof_count();
  for (const auto& [dof, w] : load.dof_weights)
    if (dof >= ndof) throw InputError("load dof out of range");
  for (const auto& p : probes)
    if (p.dof >= ndof) throw InputError("probe " + p.name + " dof out of range");
  if (st)
    for (auto d : st->dofs)
      if (d >= ndof) throw InputError("space-time dof out of range");

  const auto dim = std::size_t(model.dim);
  const double dt = opt.dt_s, c = opt.alpha_damping_per_s * dt / 2;
  const double keep = (1 - c) / (1 + c), gain = dt / (1 + c);
  std::vector<double> inv_m(ndof), load_w(ndof, 0.0);
  for (std::size_t i = 0; i < ndof; ++i) inv_m[i] = model.fixed[i] ? 0.0 : 1.0 / model.mass[i / dim];
  for (const auto& [dof, w] : load.dof_weights) load_w[dof] += w;
  std::vector<double> u(ndof, 0.0), v(ndof, 0.0), f(ndof, 0.0);

  const std::int64_t nsamples = opt.steps / opt.sample_stride + 1;
  ExplicitResult res;
  res.signals.resize(probes.size());
  for (std::size_t p = 0; p < probes.size(); ++p) {
    auto& sg = res.signals[p];
    sg.name = probes[p].name;
    sg.quantity = to_string(probes[p].quantity);
    sg.unit = si_unit(probes[p].quantity);
    sg.component = probes[p].component;
    sg.t0_s = 0;
    sg.dt_s = dt * double(opt.sample_stride);
    sg.samples.assign(std::size_t(nsamples), 0.0);
    sg.position_m = model.position(probes[p].dof / dim);
  }
  // Every recorded dof as (dof, quantity, where its samples go, their stride).
  struct Tap {
    std::size_t dof;
    MotionQuantity quantity;
    double* out;
    std::size_t stride;
    double sign;
  };
  std::vector<Tap> taps;
  for (std::size_t p = 0; p < probes.size(); ++p)
    taps.push_back({probes[p].dof, probes[p].quantity, res.signals[p].samples.data(), 1, probes[p].sign});
  if (st) {
    res.spacetime.assign(std::size_t(nsamples) * st->dofs.size(), 0.0);
    for (std::size_t j = 0; j < st->dofs.size(); ++j)
      taps.push_back({st->dofs[j], st->quantity, res.spacetime.data() + j, st->dofs.size(), 1.0});
  }
  std::sort(taps.begin(), taps.end(), [](const Tap& a, const Tap& b) { return a.dof < b.dof; });

  const Assembler A(model);
  const auto start = std::chrono::steady_clock::now();
  bool blew_up = false;
  std::exception_ptr callback_error;
  double ke_max = 0, ke_last = 0;
  const std::int64_t check_every = 200;
  std::vector<double> ke_part;

  // One step, per thread on its own dofs (no other thread writes them, so no
  // barrier is needed between reading and writing them): f = K u^n over all
  // elements (colour by colour), then
  //   v^{n+1/2} = keep v^{n-1/2} + gain (F^n w - f) / m,  u^{n+1} = u^n + dt v^{n+1/2},  f = 0,
  // and the recorded dofs sampled from v^{n-1/2}, v^{n+1/2} and u^n.
#pragma omp parallel num_threads(region_threads(model.element_count(), opt.min_elements_per_thread))
  {
#pragma omp single
    {
      res.threads = omp_get_num_threads();
      ke_part.assign(std::size_t(res.threads), 0.0);
    }
    const auto [b, e] = my_range(ndof);
    const int tid = omp_get_thread_num();
    const auto tap_begin = std::lower_bound(taps.begin(), taps.end(), b, [](const Tap& t, std::size_t d) { return t.dof < d; });
    const auto tap_end = std::lower_bound(taps.begin(), taps.end(), e, [](const Tap& t, std::size_t d) { return t.dof < d; });
    for (std::int64_t n = 0; n <= opt.steps; ++n) {
      const double F = opt.unit_impulse ? (n == 0 ? 1.0 : 0.0) : load.burst(double(n) * dt);
      A.add(u.data(), f.data());  // ends with a barrier: f = K u^n complete
      if (n % opt.sample_stride == 0) {
        const auto k = std::size_t(n / opt.sample_stride);
        for (auto t = tap_begin; t != tap_end; ++t) {
          const std::size_t i = t->dof;
          const double v_new = keep * v[i] + gain * (F * load_w[i] - f[i]) * inv_m[i];
          double value = 0;
          switch (t->quantity) {
            case MotionQuantity::displacement: value = u[i]; break;
            case MotionQuantity::velocity: value = 0.5 * (v_new + v[i]); break;
            case MotionQuantity::acceleration: value = (v_new - v[i]) / dt; break;
          }
          t->out[k * t->stride] = t->sign * value;
        }
      }
      for (std::size_t i = b; i < e; ++i) {
        v[i] = keep * v[i] + gain * (F * load_w[i] - f[i]) * inv_m[i];
        u[i] += dt * v[i];
        f[i] = 0.0;
      }
      if (n % check_every == 0 || n == opt.steps) {
        double ke = 0;
        for (std::size_t i = b; i < e; ++i) ke += 0.5 * model.mass[i / dim] * v[i] * v[i];
        ke_part[std::size_t(tid)] = ke;
#pragma omp barrier
#pragma omp single
        {
          double sum = 0;
          for (double k : ke_part) sum += k;  // fixed order: same bits for any thread count
          if (!std::isfinite(sum)) blew_up = true;
          ke_max = std::max(ke_max, sum);
          ke_last = sum;
          // An exception may not leave an OpenMP region: the callback's (an interrupted run's,
          // app/interrupt.hpp) is kept, every thread leaves the loop, and it is rethrown after.
          if (opt.progress && !callback_error) try {
              opt.progress(n);
            } catch (...) {
              callback_error = std::current_exception();
            }
        }
        if (blew_up || callback_error) break;
      } else {
#pragma omp barrier
      }
    }
  }
  if (callback_error) std::rethrow_exception(callback_error);
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (blew_up && !opt.allow_unstable)
    throw std::runtime_error("the explicit solution stopped being finite (unstable step or bad input)");
  res.steps = opt.steps;
  res.max_kinetic_energy_J = ke_max;
  res.final_kinetic_energy_J = ke_last;
  return res;
}

}  // namespace mesowave::fem
