// Writes the seeds of the checkpoint_hdf5 fuzz target: checkpoints of its own run
// (tests/fuzz/checkpoint_hdf5.cpp) after 0, 25 and 50 (all) steps. A one-off program, not part of
// the build (tests/fuzz/corpus/README.md says how to build and run it).
#include <filesystem>
#include <iostream>

#include "../checkpoint_hdf5.cpp"

int main(int argc, char** argv) {
  namespace c = mesowave::fuzz::checkpoint;
  if (argc != 2) {
    std::cerr << "usage: make_checkpoint_seeds tests/fuzz/corpus\n";
    return 1;
  }
  const std::filesystem::path dir = std::filesystem::path(argv[1]) / "checkpoint_hdf5";
  std::filesystem::create_directories(dir);
  for (const int step : {0, 25, 50}) {
    struct Stop {};
    mesowave::dem::SimulationOptions o;
    o.on_progress = [&](std::int64_t done, std::int64_t) {
      if (done == step) throw Stop{};
    };
    mesowave::dem::Simulation sim(c::scene(), c::packing(), o);
    if (step > 0) try {
        sim.run();
      } catch (const Stop&) {
      }
    sim.save_checkpoint(dir / ("step-" + std::to_string(step) + ".h5"), c::identity());
    std::cout << "step " << step << ": " << sim.model().broken_bond_count() << " of " << sim.model().bond_count()
              << " bonds broken, " << sim.model().contact_count() << " contacts\n";
  }
  return 0;
}
