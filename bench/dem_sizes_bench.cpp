// Cost of the DEM step against size, side by side (issue 17 item 5; docs/benchmarks.md, "Cost
// against size", session 5): one model per packing, all in one process, stepped in turns - a
// block of steps of the first, then of the second, ... - for several rounds, so that every size
// sees the same machine. On the shared VMs the speed of memory wanders by up to 2x over minutes:
// sizes measured one after the other (cost_vs_size.sh) mix that drift into the exponent.
// Prints each size's median ms per step over the rounds (and quartiles), the ns per bond-step,
// and the exponent b of ms per step ~ spheres^b (least squares in log-log). With --profile-s it
// steps one model alone, for a profiler attached after the set-up (docs/benchmarks.md, sixth part).
// With a --compare-* option each turn is two blocks, the model as the engine makes it (A) and a
// variant (B), in an order alternating from round to round: the ratio B / A in one process.
//   --compare-prefetch-ahead N: B's contacts ask N ahead for their second spheres' lines, A's
//     for none (SphereSystem::set_prefetch_ahead, on the one model; the same bits; eighth part);
//   --compare-spheres-per-partition N: B is a second model of the packing laid out in partitions
//     of about N spheres (SphereSystem::partition_count; other bits; ninth part);
//   --compare-every-acceleration: B keeps every sphere's acceleration, A only the 50 observed
//     spheres' (Model::observe, on the one model; the same bits; tenth part).
//
//   build/bin/bench_dem_sizes --model linear --threads 1 p32.h5 p50.h5 p75.h5 p150.h5
//   build/bin/bench_dem_sizes --model linear --profile-s 20 p150.h5   # then perf record -p PID
//   build/bin/bench_dem_sizes --model full --compare-prefetch-ahead 128 p32.h5 p50.h5
//   build/bin/bench_dem_sizes --model full --compare-spheres-per-partition 4096 p32.h5 p50.h5
//   build/bin/bench_dem_sizes --model linear --compare-every-acceleration p32.h5 p50.h5
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "dem_step_model.hpp"
#include "mesowave/core/threads.hpp"
#include "mesowave/dem/contact/cohesive_frictional_contact.hpp"
#include "mesowave/dem/contact/linear_bonded_network.hpp"

using namespace mesowave;

namespace {

/// The value of rank q (n - 1) rounded to the nearest, ties away from the median (of an even count
/// the median is the upper middle value), as bench/paired_ratios.py takes it.
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double rank = q * double(v.size() - 1);
  return v[std::size_t(q < 0.5 ? std::ceil(rank - 0.5) : std::floor(rank + 0.5))];
}

/// The slope of log y against log x (least squares).
double exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]), my += std::log(y[i]);
  mx /= double(x.size()), my /= double(x.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = std::log(x[i]) - mx;
    sxy += dx * (std::log(y[i]) - my), sxx += dx * dx;
  }
  return sxy / sxx;
}

/// Steps `model` for at least `ms` of wall time, whole steps; the wall ms per step.
double ms_per_step(dem::SphereSystem& model, double ms) {
  const auto start = std::chrono::steady_clock::now();
  int steps = 0;
  double elapsed = 0;
  do {
    model.step(5e-8, false);
    ++steps;
    elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < ms);
  return elapsed / steps;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The DEM step's cost against size: the packings' models stepped in turns in one process"};
  std::string model_name = "linear", csv;
  int threads = 1, rounds = 12;
  double block_ms = 500, profile_s = 0;
  int compared = 0, compared_partition = 0;
  bool compared_every_acceleration = false;
  std::vector<std::string> packings;
  app.add_option("--model", model_name, "Contact law: linear (the linearised network) or full")
      ->check(CLI::IsMember({"linear", "full"}));
  app.add_option("--threads", threads, "Threads per step")->check(CLI::PositiveNumber);
  app.add_option("--rounds", rounds, "Turns per model (the medians are over these)")->check(CLI::PositiveNumber);
  app.add_option("--block-ms", block_ms, "Wall time of one turn [ms] (whole steps: at least one)")->check(CLI::PositiveNumber);
  app.add_option("--csv", csv, "Also write one row per packing to this CSV file");
  app.add_option("--profile-s", profile_s,
                 "Instead of the rounds: once built, step the first packing's model alone for this long [s], "
                 "its process id printed first, so that a profiler attached then (perf record -p PID) sees the "
                 "steady step without the set-up (which takes longer than the steps at 1 M spheres)")
      ->check(CLI::PositiveNumber);
  auto* prefetch_option =
      app.add_option("--compare-prefetch-ahead", compared,
                     "Instead of the engine's choice (" + std::to_string(dem::SphereSystem::kPrefetchAhead) + " from " +
                         std::to_string(dem::SphereSystem::kPrefetchFromSpheres) +
                         " held spheres on, else 0), step each model in every turn twice: its chunks asking this many "
                         "contacts ahead for their second spheres' lines (B), and asking for none (A), the order "
                         "alternating from round to round; prints the medians of both and of the rounds' ratios B / A. "
                         "The exponent is A's")
          ->check(CLI::Range(1, 1 << 20));
  auto* partition_option = app.add_option("--compare-spheres-per-partition", compared_partition,
                 "Also build each packing's model laid out in partitions of about this many spheres (B; the engine's "
                 "is " + std::to_string(dem::SphereSystem::kSpheresPerPartition) +
                     ", at least " + std::to_string(dem::SphereSystem::kMinPartitions) + " partitions where " +
                     std::to_string(dem::SphereSystem::kSpheresPerPartitionMin) + " spheres each allow it, at most " +
                     std::to_string(dem::SphereSystem::kMaxPartitions) +
                     "; other bits) and step both in every turn, the order alternating from round to round; prints "
                     "the medians of both and of the rounds' ratios B / A (A: the engine's layout). The exponent is A's")
      ->check(CLI::Range(dem::SphereSystem::kSpheresPerPartitionMin, std::size_t(1) << 24))
      ->excludes(prefetch_option);
  app.add_flag("--compare-every-acceleration", compared_every_acceleration,
               "Step each model in every turn twice: keeping every sphere's acceleration (B) and only the " +
                   std::to_string(bench::kPushedSpheres) +
                   " observed spheres' blocks' (A, as a run keeps those of its sensors and actuators: "
                   "Model::observe), the order alternating from round to round; prints the medians of both and of "
                   "the rounds' ratios B / A (the same bits). The exponent is A's")
      ->excludes(prefetch_option)
      ->excludes(partition_option);
  app.add_option("packings", packings, "mw-pack packing files (HDF5), smallest first")->required()->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);
  if (packings.size() < 2 && profile_s == 0) {
    std::fprintf(stderr, "error: give at least two packings (an exponent needs two sizes) or --profile-s, got %zu\n", packings.size());
    return 1;
  }

  use_threads(threads);
  const auto build = [&](const dem::Packing& packing, std::size_t spheres_per_partition) {
    return model_name == "full" ? bench::step_model<dem::CohesiveFrictionalContact>(packing, spheres_per_partition)
                                : bench::step_model<dem::LinearBondedNetwork>(packing, spheres_per_partition);
  };
  // Per packing the model as the engine makes it and, with --compare-spheres-per-partition, its variant.
  std::vector<std::unique_ptr<dem::SphereSystem>> models, variants;
  for (const std::string& file : packings) {
    const dem::Packing packing = dem::read_packing_file(file);
    models.push_back(build(packing, dem::SphereSystem::kSpheresPerPartition));
    std::fprintf(stderr, "# %s: %zu spheres, %zu bonds, built (%zu partitions; its contacts ask %zu ahead)\n", file.c_str(),
                 models.back()->sphere_count(), models.back()->bond_count(),
                 dem::SphereSystem::partition_count(models.back()->sphere_count()), models.back()->prefetch_ahead());
    if (compared_partition > 0) {
      variants.push_back(build(packing, std::size_t(compared_partition)));
      std::fprintf(stderr, "#   and its variant in %zu partitions\n",
                   dem::SphereSystem::partition_count(models.back()->sphere_count(), std::size_t(compared_partition)));
    }
  }
  const bool comparing = compared > 0 || compared_partition > 0 || compared_every_acceleration;
  // Readies turn `which` (0: A, 1: B) of packing m and returns the model it steps.
  const auto variant = [&](std::size_t m, int which) -> dem::SphereSystem& {
    if (compared > 0) models[m]->set_prefetch_ahead(which == 0 ? 0 : std::size_t(compared));
    if (compared_every_acceleration)
      models[m]->observe(bench::first_spheres(which == 0 ? bench::kPushedSpheres : models[m]->sphere_count()));
    return which == 1 && compared_partition > 0 ? *variants[m] : *models[m];
  };
  if (profile_s > 0) {
    std::printf("# process %d: %s alone for %g s\n", int(getpid()), packings[0].c_str(), profile_s);
    std::fflush(stdout);
    std::printf("%s: %.4g ms/step\n", packings[0].c_str(), ms_per_step(*models[0], 1e3 * profile_s));
    return 0;
  }
  std::vector<std::vector<double>> step_ms(models.size()), variant_ms(models.size()), ratios(models.size());
  for (int round = 0; round < rounds; ++round)
    for (std::size_t m = 0; m < models.size(); ++m) {
      const int turns = comparing ? 2 : 1;
      double ms[2] = {};  // A, B
      for (int turn = 0; turn < turns; ++turn) {
        const int which = (turn + round) % turns;
        dem::SphereSystem& model = variant(m, which);
        model.step(5e-8, false);  // the caches hold the last model's data: one step to take them back
        ms[which] = ms_per_step(model, block_ms);
      }
      step_ms[m].push_back(ms[0]);
      if (comparing) variant_ms[m].push_back(ms[1]), ratios[m].push_back(ms[1] / ms[0]);
    }

  std::ofstream out;
  if (!csv.empty()) {
    out.open(csv);
    out << "packing,model,threads,spheres,bonds,rounds,ms_per_step_median,ms_per_step_q1,ms_per_step_q3,ns_per_bond_step\n";
  }
  std::vector<double> spheres, medians;
  const std::string variant_name = compared > 0                  ? "asking " + std::to_string(compared) + " ahead"
                                   : compared_every_acceleration ? std::string("every acceleration kept")
                                                                 : "partitions of " + std::to_string(compared_partition) + " spheres";
  std::printf("# %s, %d thread(s), %d rounds of %.0f ms a model%s\n", model_name.c_str(), threads, rounds, block_ms,
              !comparing                    ? ""
              : compared > 0                ? " and setting (first rows, A: asking for no lines ahead)"
              : compared_every_acceleration ? " and setting (first rows, A: the observed spheres' accelerations kept)"
                                            : " and layout (first rows, A: the engine's partitions)");
  for (std::size_t m = 0; m < models.size(); ++m) {
    const double median = quantile(step_ms[m], 0.5), q1 = quantile(step_ms[m], 0.25), q3 = quantile(step_ms[m], 0.75);
    const double bonds = double(models[m]->bond_count()), ns_per_bond = 1e6 * median / bonds;
    std::printf("%-40s %9zu spheres %9.0f bonds  %9.4g ms/step (quartiles %.4g-%.4g)  %6.3g ns/bond-step\n", packings[m].c_str(),
                models[m]->sphere_count(), bonds, median, q1, q3, ns_per_bond);
    if (out) out << packings[m] << ',' << model_name << ',' << threads << ',' << models[m]->sphere_count() << ',' << bonds << ','
                 << rounds << ',' << median << ',' << q1 << ',' << q3 << ',' << ns_per_bond << '\n';
    if (comparing)
      std::printf("%-40s   B, %s: %.4g ms/step; B / A: median %.3f (quartiles %.3f-%.3f)\n", "", variant_name.c_str(),
                  quantile(variant_ms[m], 0.5), quantile(ratios[m], 0.5), quantile(ratios[m], 0.25), quantile(ratios[m], 0.75));
    spheres.push_back(double(models[m]->sphere_count())), medians.push_back(median);
  }
  std::printf("exponent b of ms/step ~ spheres^b: %.3f\n", exponent(spheres, medians));
  return 0;
}
