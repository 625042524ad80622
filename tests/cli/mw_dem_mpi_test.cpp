// mpirun -np N mw-dem run (docs/mpi.md): the same files, byte for byte, as one process, for
// N = 1-4 ranks (oversubscribed on a small machine) - a wave in the linearised network and in
// the full law, and a compression to failure (the same bonds broken, the same curve); a
// checkpoint is one process's file and restarts on any rank count, also one a signal to a
// single rank asked for; the options a distributed run does not take are refused in one line.
// The reference is the single-process engine itself, run without any MPI launcher.
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <future>
#include <limits>
#include <regex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "dem/checkpoint_edits.hpp"
#include "dem/test_packings.hpp"
#include "mesowave/dem/packing/packing_file.hpp"
#include "mesowave/prov/database.hpp"
#include "mesowave/prov/queries.hpp"
#include "mesowave/signal/signal_file.hpp"
#include "support/run_tool.hpp"

using namespace mesowave;
using test::run_tool;

namespace {

// OpenMPI as the tests run it: as root (the containers' user), shared memory only (no
// network probing), more ranks than cores.
const std::vector<std::string> kMpiEnv = {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1",
                                          "OMPI_MCA_btl=self,vader", "OMPI_MCA_btl_vader_single_copy_mechanism=none",
                                          "OMPI_MCA_mpi_yield_when_idle=1"};

// `env`: more variables for the ranks. Under `timeout`, so that ranks left waiting by a failed
// one end the test (exit 124) instead of hanging it.
// `program`: what each rank runs, mw-dem unless given.
test::ToolResult mpirun(int ranks, const std::vector<std::string>& args, const std::vector<std::string>& env = {},
                        const std::string& program = test::tool_path("mw-dem").string()) {
  std::vector<std::string> command = {"120", "/usr/bin/mpirun", "--oversubscribe", "-np", std::to_string(ranks), program};
  command.insert(command.end(), args.begin(), args.end());
  std::vector<std::string> environment = kMpiEnv;
  environment.insert(environment.end(), env.begin(), env.end());
  return test::run_command("/usr/bin/timeout", command, environment);
}

// The runs a database holds (mw-dem records on rank 0, or a failure only another rank saw there).
std::vector<prov::RunRecord> recorded_runs(const std::filesystem::path& db_path) {
  const auto db = prov::Database::open(db_path);
  std::vector<prov::RunRecord> runs;
  for (const auto& r : prov::list_runs(db)) runs.push_back(prov::load_run(db, r.id));
  return runs;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// `text` with each edit's first text replaced by its second; std::logic_error (the test fails with
// it) if one is missing, so that an edit never silently does nothing.
std::string edited(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("the scene has no \"" + from + "\" to edit");
    text.replace(at, from.size(), to);
  }
  return text;
}

// The 6-cell FCC block (864 spheres: four 256-sphere blocks, so four ranks each hold some).
void write_block(const test::TempDir& dir) { dem::write_packing_file(dir / "block.h5", dem::testing::crushing_block(6)); }

// crush.toml: the shared crushing scene on the block, made shorter for the larger block (the wall
// 2.4 x faster, the stop 20 % past the peak): about 2,700 steps to failure.
void write_crush_scene(const test::TempDir& dir) {
  test::write_file(dir / "crush.toml", edited(dem::testing::crushing_scene_toml((dir / "block.h5").string()),
                                              {{"velocity_mm_s = 500.0", "velocity_mm_s = 1200.0"},
                                               {"ramp_us = 20", "ramp_us = 10"},
                                               {"stop_drop_pct = 50.0", "stop_drop_pct = 20.0"}}));
}

// A burst on face z- of the block, accelerations on the opposite face and a side face.
std::string wave_scene(const std::filesystem::path& packing) {
  return R"(
[packing]
file = ")" + packing.string() + R"("
[material]
E_dem_GPa = 23.31
nu_dem = 0.32
friction_angle_deg = 18.0
T_MPa = 24.4
C_MPa = 24.4
damping = 0.01
bond_factor = 1.1
[time]
dt_ns = 40
duration_ms = 0.016
[[actuator]]
name = "A"
kind = "force"
face = "z-"
centre_rel = [0.5, 0.5, 0]
patch_mm = [3.0, 3.0]
direction = "inward"
amplitude_N = 0.01
frequency_kHz = 250
cycles = 3
[[sensor]]
name = "B"
quantity = "acceleration"
component = "normal"
face = "z+"
centre_rel = [0.5, 0.5, 1]
patch_mm = [3.0, 3.0]
[[sensor]]
name = "C"
quantity = "velocity"
component = "normal"
face = "x+"
centre_rel = [1, 0.5, 0.5]
patch_mm = [3.0, 3.0]
)";
}

// The summary without what differs between any two runs (timings, the machine's thread
// choice), the distributed run's description of its split, and rank 0's memory (its share).
nlohmann::json comparable(const std::filesystem::path& summary) {
  auto j = nlohmann::json::parse(test::read_file(summary));
  for (const char* key : {"wall_s", "setup_s", "steps_per_s", "ns_per_contact_step", "threads", "threads_reason", "mpi",
                          "memory_estimate_MiB"})
    j.erase(key);
  return j;
}

// Runs `scene` on one process and on each of `ranks` and compares every output file byte for
// byte (with `curves`, a [test]'s stress-strain curves too).
void expect_same_files_on_ranks(const test::TempDir& dir, const std::string& scene, const std::vector<std::string>& extra,
                                const std::vector<int>& ranks, bool curves = false) {
  const auto outputs = [&](const std::string& tag) {
    std::vector<std::string> o = {"--signals", (dir / (tag + ".h5")).string(), "--signals-csv",
                                  (dir / (tag + ".csv")).string(), "--summary", (dir / (tag + ".json")).string()};
    if (curves) o.insert(o.end(), {"--curves", (dir / (tag + "-curves.csv")).string()});
    return o;
  };
  const std::vector<std::string> base = with({"run", (dir / scene).string(), "--quiet"}, extra);
  const auto one = run_tool("mw-dem", with(with(base, outputs("one")), {"--threads", "1"}));
  ASSERT_EQ(one.exit_status, 0) << one.err;
  for (const int np : ranks) {
    const std::string tag = "np" + std::to_string(np);
    // Two threads per rank on one of them: neither count may change the bits.
    const auto r = mpirun(np, with(with(base, outputs(tag)), {"--threads", np == 2 ? "2" : "1"}));
    ASSERT_EQ(r.exit_status, 0) << tag << ": " << r.err;
    EXPECT_EQ(test::read_file(dir / "one.h5"), test::read_file(dir / (tag + ".h5"))) << tag;  // cmp
    EXPECT_EQ(test::read_file(dir / "one.csv"), test::read_file(dir / (tag + ".csv"))) << tag;
    if (curves) {
      EXPECT_EQ(test::read_file(dir / "one-curves.csv"), test::read_file(dir / (tag + "-curves.csv"))) << tag;
    }
    EXPECT_EQ(comparable(dir / "one.json"), comparable(dir / (tag + ".json"))) << tag;
    if (np > 1) {
      const auto j = nlohmann::json::parse(test::read_file(dir / (tag + ".json")));
      const std::string split = j.value("mpi", std::string());
      EXPECT_NE(split.find("rank 0 of " + std::to_string(np)), std::string::npos) << tag;
      // Rank 0 holds only the contacts of its own spheres (stage 3, docs/mpi.md): fewer than all.
      const auto contacts = j["contacts"].get<std::size_t>();
      const auto at = split.find(" of " + std::to_string(contacts) + " contacts and ");
      ASSERT_NE(at, std::string::npos) << split;
      const auto held = std::stoul(split.substr(split.rfind(' ', at - 1) + 1));
      EXPECT_GT(held, 0u) << split;
      EXPECT_LT(held, contacts) << split;
      // ... and made only the bonds with an end of its own (make_bond_network with the domain).
      std::smatch m;
      ASSERT_TRUE(std::regex_search(split, m, std::regex(R"((\d+) of (\d+) bonds held here)"))) << split;
      EXPECT_EQ(std::stoul(m[2].str()), j["bonds"].get<std::size_t>()) << split;
      EXPECT_GT(std::stoul(m[1].str()), 0u) << split;
      EXPECT_LT(std::stoul(m[1].str()), j["bonds"].get<std::size_t>()) << split;
      // ... and the arrays of its own spheres, its ghosts and the observed ones only (hold()).
      const std::regex spheres_held(R"(spheres (\d+)-(\d+) of (\d+) \(Morton order\), (\d+) held, (\d+) ghosts from \d+ ranks, (\d+) observed)");
      ASSERT_TRUE(std::regex_search(split, m, spheres_held)) << split;
      const auto number = [&](int k) { return std::stoul(m[k].str()); };
      EXPECT_EQ(number(3), j["spheres"].get<std::size_t>()) << split;
      EXPECT_GE(number(4), number(2) - number(1) + number(5)) << split;
      EXPECT_LE(number(4), number(2) - number(1) + number(5) + number(6)) << split;
      EXPECT_LT(number(4), number(3)) << split;
      // ... and read a part of the packing's rows, its setup a part of the spheres (stage 3, steps 10-11).
      const std::size_t spheres = number(3), own = number(2) - number(1);
      ASSERT_TRUE(std::regex_search(split, m, std::regex(R"(setup: (\d+) packing rows read, (\d+) spheres of its part)"))) << split;
      EXPECT_LE(std::stoul(m[1].str()), (spheres + std::size_t(np) - 1) / std::size_t(np)) << split;
      // (At np 2 rank 0's part of the 864-sphere blocks, 512 own spheres and a layer two radii
      // deep, reaches every sphere; not on the 8,788-sphere block, nor on the line, 259 of 600.)
      if (np >= 3 || spheres > 5000) {
        EXPECT_LT(std::stoul(m[2].str()), spheres) << split;
      }
      EXPECT_GE(std::stoul(m[2].str()), own) << split;
    }
  }
}

}  // namespace

TEST(MwDemMpi, ALinearWaveOnOneToFourRanksWritesTheSameFilesAsOneProcess) {
  test::TempDir dir;
  write_block(dir);
  test::write_file(dir / "wave.toml", wave_scene(dir / "block.h5"));
  expect_same_files_on_ranks(dir, "wave.toml", {"--model", "linear"}, {1, 2, 3, 4});
}

TEST(MwDemMpi, AFullLawWaveOnTwoToFourRanksWritesTheSameFilesAsOneProcess) {
  test::TempDir dir;
  write_block(dir);
  test::write_file(dir / "wave.toml", wave_scene(dir / "block.h5"));
  expect_same_files_on_ranks(dir, "wave.toml", {"--model", "full"}, {2, 3, 4});
  // Snapshots: rank 0 writes every sphere's position, displacement, velocity, radius and packing
  // index, gathered from the ranks that hold them (no rank holds every sphere's after the setup).
  const auto snapshots = [&](const std::string& tag) {
    return std::vector<std::string>{"run", (dir / "wave.toml").string(), "--quiet", "--model", "full", "--signals",
                                    (dir / (tag + "-s.h5")).string(), "--snapshots", (dir / tag).string(),
                                    "--snapshot-interval-us", "8", "--threads", "1"};
  };
  const auto one = run_tool("mw-dem", snapshots("snap1"));
  ASSERT_EQ(one.exit_status, 0) << one.err;
  const auto three = mpirun(3, snapshots("snap3"));
  ASSERT_EQ(three.exit_status, 0) << three.err;
  for (const char* file : {"snapshot-0.vtp", "snapshot-1.vtp", "snapshot-2.vtp", "snapshots.pvd"}) {
    const std::string vtp = test::read_file(dir / "snap1" / file);
    EXPECT_FALSE(vtp.empty()) << file;
    EXPECT_EQ(vtp, test::read_file(dir / "snap3" / file)) << file;
  }
}

// A platen (a velocity actuator) imposes its motion on the spheres under it and reports the force
// that takes, m (a_imposed - a_free) a sphere: each sphere's own mass (the block's radii differ),
// read on a rank that holds it by its local number.
TEST(MwDemMpi, APlatensForceOnTwoAndThreeRanksIsTheOneProcessForce) {
  test::TempDir dir;
  write_block(dir);
  test::write_file(dir / "platen.toml", wave_scene(dir / "block.h5") + R"(
[[actuator]]
name = "platen"
kind = "velocity"
face = "z+"
centre_rel = [0.5, 0.5, 1]
patch_mm = [20.0, 20.0]
direction = "inward"
velocity_mm_s = 25.0
ramp_us = 4
[[sensor]]
name = "F"
quantity = "force"
actuator = "platen"
)");
  expect_same_files_on_ranks(dir, "platen.toml", {"--model", "full"}, {2, 3});
  const std::string forces = test::read_file(dir / "one.csv");
  EXPECT_NE(forces.find("F [N]"), std::string::npos) << forces.substr(0, 200);
}

// The selections that are not a patch on a flat face, each combined over the ranks' parts of the
// sphere set (docs/mpi.md, stage 3 step 10), on the block's lattice without its jitter, so that
// spheres tie: a force on the sphere nearest an octahedral site mid-block (six spheres tie: the
// lowest packing index wins), sensors on the last sphere along the longest extent (a face of
// spheres across the ranks ties: the lowest Morton index wins, as one process's scan finds it), on
// the sphere nearest a point past the lower corner and under a patch on the curved face of the
// cylinder in the block's bounding box.
TEST(MwDemMpi, PointEndAndCurvedFaceSelectionsOnTwoAndThreeRanksWriteTheOneProcessFiles) {
  test::TempDir dir;
  const dem::Packing lattice = dem::testing::fcc_packing(6, 2.0e-3, 0.66e-3, 0.74e-3, 0.0, 7, 2290);
  dem::write_packing_file(dir / "lattice.h5", lattice);
  const std::string scene = edited(wave_scene(dir / "lattice.h5"),
                                   {{"face = \"z-\"\ncentre_rel = [0.5, 0.5, 0]\npatch_mm = [3.0, 3.0]\ndirection = \"inward\"",
                                     "point_mm = [5.0, 5.0, 5.0]\ndirection = \"-z\""}});
  test::write_file(dir / "select.toml", scene + R"(
[[sensor]]
name = "D"
quantity = "velocity"
component = "x"
sphere = "last"
[[sensor]]
name = "E"
quantity = "displacement"
component = "z"
point_mm = [-5.0, -5.0, -5.0]
[[sensor]]
name = "G"
quantity = "velocity"
component = "y"
face = "curved"
centre_rel = [0.5, 1, 0.5]
patch_mm = [4.0, 4.0]
)");
  expect_same_files_on_ranks(dir, "select.toml", {"--model", "full"}, {2, 3});
  // The nearest spheres are the packing's nearest, found here by a plain scan of its spheres in
  // file order (ties: the first).
  const auto nearest = [&](std::array<double, 3> point_m) {
    std::size_t best = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < lattice.size(); ++i) {
      double d2 = 0;
      for (std::size_t d = 0; d < 3; ++d) d2 += (lattice.centres_m[i][d] - point_m[d]) * (lattice.centres_m[i][d] - point_m[d]);
      if (d2 < best_d2) best = i, best_d2 = d2;
    }
    return best;
  };
  const auto j = nlohmann::json::parse(test::read_file(dir / "np3.json"));
  EXPECT_EQ(j["actuator_loads"][0]["spheres"], nlohmann::json::array({nearest({5e-3, 5e-3, 5e-3})})) << j["actuator_loads"];
  EXPECT_EQ(j["sensor_points"][3]["spheres"], nlohmann::json::array({nearest({-5e-3, -5e-3, -5e-3})})) << j["sensor_points"];
  EXPECT_GT(j["sensor_points"][4]["spheres"].size(), 1u) << j["sensor_points"];
}

// A line of spheres (the rod's 0.95 R spacing, so second neighbours bond) on several ranks: the
// line test, the patches that take the line's end spheres and the note on the bonds that skip a
// neighbour (a rank along the line from every rank's spheres) are one process's; the chain
// model, which the line would choose, runs on one process only and is refused in one line.
TEST(MwDemMpi, ALineOfSpheresOnTwoAndThreeRanksIsOneProcessesAndItsChainIsRefused) {
  test::TempDir dir;
  dem::write_packing_file(dir / "line.h5", dem::testing::line_packing(600, 1e-3, 0.95e-3, 7800));
  test::write_file(dir / "line.toml", edited(wave_scene(dir / "line.h5"),
                                             {{"face = \"z-\"\ncentre_rel = [0.5, 0.5, 0]", "face = \"x-\"\ncentre_rel = [0, 0.5, 0.5]"},
                                              {"face = \"z+\"\ncentre_rel = [0.5, 0.5, 1]", "face = \"x+\"\ncentre_rel = [1, 0.5, 0.5]"},
                                              {"duration_ms = 0.016", "duration_ms = 0.004"}}));
  expect_same_files_on_ranks(dir, "line.toml", {"--model", "linear"}, {2, 3});
  const auto j = nlohmann::json::parse(test::read_file(dir / "np3.json"));
  EXPECT_EQ(j["actuator_loads"][0]["spheres"], nlohmann::json::array({0})) << j["actuator_loads"];
  EXPECT_EQ(j["sensor_points"][0]["spheres"], nlohmann::json::array({599})) << j["sensor_points"];
  EXPECT_NE(j["notes"].dump().find("598 of 1197 bonds link spheres that are not neighbours on the line"), std::string::npos)
      << j["notes"];
  const auto chain = mpirun(2, {"run", (dir / "line.toml").string(), "--quiet", "--signals", (dir / "chain.h5").string()});
  EXPECT_EQ(chain.exit_status, 1);
  EXPECT_NE(chain.err.find("the chain model runs on one process only"), std::string::npos) << chain.err;
  EXPECT_EQ(occurrences(chain.err, "error: "), 1u) << chain.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "chain.h5"));
}

// Each rank reads a part of the packing's rows and the ranks sort them along the Morton curve
// between them (docs/mpi.md, stage 3 step 11): the numbering must be one process's. The block's
// rows are written in reverse, and a twin of the first sphere 2 nm from it (the same Morton cell:
// the codes tie, the packing index decides) is appended last.
TEST(MwDemMpi, APackingReadInPartsIsNumberedAsOneProcessNumbersIt) {
  test::TempDir dir;
  dem::Packing block = dem::testing::crushing_block(6);
  std::reverse(block.centres_m.begin(), block.centres_m.end());
  std::reverse(block.radii_m.begin(), block.radii_m.end());
  block.centres_m.push_back({block.centres_m[0][0] + 2e-9, block.centres_m[0][1], block.centres_m[0][2]});
  block.radii_m.push_back(block.radii_m[0]);
  block.ids.push_back(std::int64_t(block.ids.size()));
  dem::write_packing_file(dir / "shuffled.h5", block);
  // The twins' bond is stiff in shear (a K_s (r_i + r_j) / |x_j - x_i|): a 1 ns step, 300 steps.
  test::write_file(dir / "wave.toml",
                   edited(wave_scene(dir / "shuffled.h5"), {{"dt_ns = 40", "dt_ns = 1"}, {"duration_ms = 0.016", "duration_ms = 0.0003"}}));
  expect_same_files_on_ranks(dir, "wave.toml", {"--model", "linear"}, {2, 3, 4});
}

// A packing with bad rows in two ranks' parts (np 3 reads rows 0-287, 288-575, 576-863): every
// rank stops with the one line one process prints, naming the file's first bad row, not
// whichever rank's check ends first; nothing is written.
TEST(MwDemMpi, BadPackingRowsOnTwoRanksEndEveryRankWithTheOneProcessLineForTheFirst) {
  test::TempDir dir;
  dem::Packing block = dem::testing::crushing_block(6);
  block.radii_m[400] = -0.5e-3;
  block.centres_m[700][1] = std::numeric_limits<double>::quiet_NaN();
  dem::write_packing_file(dir / "bad.h5", block);
  test::write_file(dir / "wave.toml", wave_scene(dir / "bad.h5"));
  const auto one = run_tool("mw-dem", {"run", (dir / "wave.toml").string(), "--quiet", "--signals", (dir / "one.h5").string()});
  EXPECT_EQ(one.exit_status, 1);
  EXPECT_NE(one.err.find("error: sphere 400 has radius -0.0005 m; radii must be positive"), std::string::npos) << one.err;
  const auto three = mpirun(3, {"run", (dir / "wave.toml").string(), "--quiet", "--signals", (dir / "np3.h5").string()});
  EXPECT_EQ(three.exit_status, 1) << three.err;
  EXPECT_NE(three.err.find("error: sphere 400 has radius -0.0005 m; radii must be positive"), std::string::npos) << three.err;
  EXPECT_EQ(occurrences(three.err, "error: "), 1u) << three.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "one.h5"));
  EXPECT_FALSE(std::filesystem::exists(dir / "np3.h5"));
}

// Bonds break, contacts are detected and relaid out, friction dissipates: the same bits.
TEST(MwDemMpi, ACompressionToFailureOnTwoToFourRanksBreaksTheSameBondsAndWritesTheSameCurve) {
  test::TempDir dir;
  write_block(dir);
  write_crush_scene(dir);
  expect_same_files_on_ranks(dir, "crush.toml", {}, {2, 3, 4}, true);
  const auto j = nlohmann::json::parse(test::read_file(dir / "one.json"));
  EXPECT_GT(j["broken_bonds"].get<int>(), 100);
  EXPECT_GT(j["energy"]["plastic_dissipated_J"].get<double>(), 0.0);
  EXPECT_FALSE(j["stop_reason"].get<std::string>().empty());  // it ran to failure
  for (const char* np : {"np2.json", "np3.json", "np4.json"})
    EXPECT_EQ(j["broken_bonds"], nlohmann::json::parse(test::read_file(dir / np))["broken_bonds"]) << np;
}

// More contacts than one partition holds (crushing_block(13): 8,788 spheres, two partitions, so
// contacts inside each and across them, in groups that the ranks' sphere ranges cut), and
// detected ones among them (bond factor C_f 1.0: a neighbour just apart is a frictional contact,
// not a bond): each rank detects its own contacts and places them in the whole layout from the
// ranks' counts (set_contacts), and the files are one process's - a wave, and a compression
// that detects contacts and drops them as it goes (11 passes, each a new layout).
TEST(MwDemMpi, DetectedContactsOfTwoPartitionsLaidOutFromTheRanksCountsWriteTheSameFiles) {
  test::TempDir dir;
  dem::write_packing_file(dir / "block.h5", dem::testing::crushing_block(13));
  const auto unbonded = [](const std::string& scene) { return edited(scene, {{"bond_factor = 1.1", "bond_factor = 1.0"}}); };
  test::write_file(dir / "wave.toml", unbonded(wave_scene(dir / "block.h5")));
  expect_same_files_on_ranks(dir, "wave.toml", {"--model", "full", "--duration-ms", "0.004"}, {2, 3});
  const auto wave = nlohmann::json::parse(test::read_file(dir / "one.json"));
  // Its checkpoint at np 3 is one process's file: rank 0 writes each array in pieces of 97 rows,
  // which cut the reporters' runs where they alternate (each group's bonds, then its pairs, rank
  // after rank), so a piece's values are not in the ranks' order.
  const auto checkpoint = [&](const std::string& tag) {
    return std::vector<std::string>{"run", (dir / "wave.toml").string(), "--quiet", "--model", "full", "--duration-ms", "0.004",
                                    "--signals", (dir / (tag + "-ckpt.h5")).string(), "--checkpoint",
                                    (dir / (tag + ".ckpt.h5")).string(), "--checkpoint-every-steps", "60"};
  };
  ASSERT_EQ(run_tool("mw-dem", checkpoint("one")).exit_status, 0);
  const auto pieces = mpirun(3, checkpoint("np3"), {"MESOWAVE_TEST_CHECKPOINT_PIECE_ROWS=97"});
  ASSERT_EQ(pieces.exit_status, 0) << pieces.err;
  EXPECT_EQ(test::read_file(dir / "one.ckpt.h5"), test::read_file(dir / "np3.ckpt.h5"));  // cmp
  write_crush_scene(dir);
  const std::string crush = unbonded(test::read_file(dir / "crush.toml"));
  test::write_file(dir / "crush.toml", crush.substr(0, crush.find("[test]")));  // before the peak: no test's analysis
  expect_same_files_on_ranks(dir, "crush.toml", {"--duration-ms", "0.08"}, {3});
  const auto crushed = nlohmann::json::parse(test::read_file(dir / "one.json"));
  EXPECT_GT(wave["contacts"].get<std::size_t>(), wave["bonds"].get<std::size_t>());     // pairs at step 0
  EXPECT_NE(crushed["contacts"].get<std::size_t>(), wave["contacts"].get<std::size_t>());  // detected anew
}

// A checkpoint written on several ranks holds the whole layout in its slot order: it is the
// same file, byte for byte, as one process's at that step, and a restart on another rank count
// writes the files of the run that never stopped - bonds broken before and after it, contacts
// detected anew, friction (the compression below), and the moment law's bending and twisting
// moments (a wave). The checkpoint has no rank count of its own.
TEST(MwDemMpi, ACheckpointOfTwoRanksIsTheOneProcessFileAndRestartsOnThreeToTheSameFiles) {
  test::TempDir dir;
  write_block(dir);
  write_crush_scene(dir);
  std::string moment = wave_scene(dir / "block.h5");
  moment.replace(moment.find("bond_factor = 1.1"), 17, "bond_factor = 1.1\nlaw = \"cohesive_moment\"");
  test::write_file(dir / "moment.toml", moment);
  for (const auto& [scene, every, extra] : {std::tuple<std::string, std::string, std::vector<std::string>>{"crush", "1000", {}},
                                            {"moment", "150", {"--model", "full"}}}) {
    const auto outputs = [&, scene = scene](const std::string& tag) {
      return std::vector<std::string>{"--signals", (dir / (scene + tag + ".h5")).string(), "--signals-csv",
                                      (dir / (scene + tag + ".csv")).string()};
    };
    const std::vector<std::string> base = with({"run", (dir / (scene + ".toml")).string(), "--quiet", "--threads", "1"}, extra);
    const auto checkpoint = [&, scene = scene, every = every](const std::string& tag) {
      return std::vector<std::string>{"--checkpoint", (dir / (scene + tag + ".refused.h5")).string(), "--checkpoint-every-steps", every};
    };
    const auto one = run_tool("mw-dem", with(with(base, outputs("-one")), checkpoint("-one")));
    ASSERT_EQ(one.exit_status, 0) << scene << ": " << one.err;
    // Rank 0 writes each array in pieces of 97 rows here (StateGroup::kPieceRows in a run): they
    // cut the ranks' sphere ranges.
    const auto two = mpirun(2, with(with(base, outputs("-np2")), checkpoint("-np2")), {"MESOWAVE_TEST_CHECKPOINT_PIECE_ROWS=97"});
    ASSERT_EQ(two.exit_status, 0) << scene << ": " << two.err;
    EXPECT_EQ(test::read_file(dir / (scene + "-one.h5")), test::read_file(dir / (scene + "-np2.h5"))) << scene;
    EXPECT_EQ(test::read_file(dir / (scene + "-one.refused.h5")), test::read_file(dir / (scene + "-np2.refused.h5"))) << scene;  // cmp
    // ... and the restart reads the contact list in rounds of three ranks' 97-row pieces.
    const auto again = mpirun(3, with(with(base, outputs("-np3")), {"--restart", (dir / (scene + "-np2.refused.h5")).string()}),
                              {"MESOWAVE_TEST_CHECKPOINT_PIECE_ROWS=97"});
    ASSERT_EQ(again.exit_status, 0) << scene << ": " << again.err;
    EXPECT_EQ(test::read_file(dir / (scene + "-one.h5")), test::read_file(dir / (scene + "-np3.h5"))) << scene;
    EXPECT_EQ(test::read_file(dir / (scene + "-one.csv")), test::read_file(dir / (scene + "-np3.csv"))) << scene;
  }
  // The same checkpoint with the first slot's bond index set to the last bonded slot's: that bond
  // twice, the first slot's own once less. Each rank checks only the bonds it holds (made per rank),
  // and every rank refuses it, in one line, before a step.
  std::filesystem::copy_file(dir / "crush-np2.refused.h5", dir / "swapped.h5");
  ASSERT_NO_FATAL_FAILURE(test::give_the_first_slot_the_last_bond(dir / "swapped.h5"));
  const auto refused = mpirun(2, {"run", (dir / "crush.toml").string(), "--quiet", "--threads", "1", "--signals",
                                  (dir / "refused.h5").string(), "--restart", (dir / "swapped.h5").string()});
  EXPECT_EQ(refused.exit_status, 1) << refused.err;
  EXPECT_NE(refused.err.find("its bonds are not this packing's"), std::string::npos) << refused.err;
  EXPECT_EQ(occurrences(refused.err, "error: "), 1u) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "refused.h5"));
  // Row 100's contact to sphere 864, past the block's: rank 1 reads that row (three ranks, rows
  // 97-193 its first piece of 97) and finds it, and every rank refuses the checkpoint in one line.
  std::filesystem::copy_file(dir / "crush-np2.refused.h5", dir / "unfit.h5");
  ASSERT_NO_FATAL_FAILURE(test::set_a_contacts_end(dir / "unfit.h5", "second", 100, 864));
  const auto unfit = mpirun(3, {"run", (dir / "crush.toml").string(), "--quiet", "--threads", "1", "--signals",
                                (dir / "unfit-signals.h5").string(), "--restart", (dir / "unfit.h5").string()},
                            {"MESOWAVE_TEST_CHECKPOINT_PIECE_ROWS=97"});
  EXPECT_EQ(unfit.exit_status, 1) << unfit.err;
  EXPECT_NE(unfit.err.find("its contacts do not fit this packing's 864 spheres"), std::string::npos) << unfit.err;
  EXPECT_EQ(occurrences(unfit.err, "error: "), 1u) << unfit.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "unfit-signals.h5"));
  // Values that are no index in rows read by three ranks (97-row pieces: rows 100 and 200 are the
  // first round's of ranks 1 and 2, row 300 the second round's of rank 0): every rank refuses the
  // checkpoint with the one line one process prints, for the file's first (was: whichever rank
  // printed first, often two lines).
  std::filesystem::copy_file(dir / "crush-np2.refused.h5", dir / "nonindex.h5");
  ASSERT_NO_FATAL_FAILURE(test::set_a_contacts_end(dir / "nonindex.h5", "first", 100, -7));
  ASSERT_NO_FATAL_FAILURE(test::set_a_contacts_end(dir / "nonindex.h5", "second", 200, std::int64_t(1) << 40));
  ASSERT_NO_FATAL_FAILURE(test::set_a_contacts_end(dir / "nonindex.h5", "first", 300, -3));
  const std::string nonindex = "nonindex.h5:/model/law/first holds -7, not an index";
  const std::vector<std::string> restart = {"run", (dir / "crush.toml").string(), "--quiet", "--threads", "1", "--signals",
                                            (dir / "nonindex-signals.h5").string(), "--restart", (dir / "nonindex.h5").string()};
  const auto one_refused = run_tool("mw-dem", restart);
  EXPECT_EQ(one_refused.exit_status, 1) << one_refused.err;
  EXPECT_NE(one_refused.err.find(nonindex), std::string::npos) << one_refused.err;
  const auto three_refused = mpirun(3, restart, {"MESOWAVE_TEST_CHECKPOINT_PIECE_ROWS=97"});
  EXPECT_EQ(three_refused.exit_status, 1) << three_refused.err;
  EXPECT_NE(three_refused.err.find(nonindex), std::string::npos) << three_refused.err;
  EXPECT_EQ(occurrences(three_refused.err, "error: "), 1u) << three_refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "nonindex-signals.h5"));
}

// SIGTERM to rank 1 alone, mid-run (Slurm signals each task itself, at its own moment): the
// ranks agree on it after the step, so rank 0, which caught nothing, writes the checkpoint and
// every rank stops after that step - exit 143, one error line naming the checkpoint, one record
// (rank 0's). A restart on three ranks writes the signals of the run that never stopped.
TEST(MwDemMpi, ASignalToOneRankStopsEveryRankAfterOneCheckpointThatRestartsToTheSameFiles) {
  test::TempDir dir;
  write_block(dir);
  test::write_file(dir / "wave.toml", wave_scene(dir / "block.h5"));
  const std::vector<std::string> base = {"run", (dir / "wave.toml").string(), "--model", "full", "--threads", "1",
                                         "--duration-ms", "0.6"};  // 15,000 steps
  const auto one = run_tool("mw-dem", with(base, {"--quiet", "--signals", (dir / "one.h5").string()}));
  ASSERT_EQ(one.exit_status, 0) << one.err;
  // Each rank writes its pid and its stderr to files, so that the test can signal rank 1 once rank 0
  // reports 10 % of the steps.
  std::string command = "echo $$ > " + (dir / "pid.").string() + "$OMPI_COMM_WORLD_RANK; exec " +
                        test::tool_path("mw-dem").string();
  for (const auto& a : with(base, {"--signals", (dir / "s.h5").string(), "--checkpoint", (dir / "c.h5").string(), "--db",
                                   (dir / "p.sqlite").string()}))
    command += " " + a;
  command += " 2> " + (dir / "err.").string() + "$OMPI_COMM_WORLD_RANK";
  auto stopped = std::async(std::launch::async, [&] { return mpirun(2, {"-c", command}, {}, "/bin/sh"); });
  bool signalled = false;
  for (int i = 0; i < 12000 && !signalled; ++i) {  // at most 120 s, as mpirun's timeout
    if (stopped.wait_for(std::chrono::milliseconds(10)) == std::future_status::ready) break;
    if (std::filesystem::exists(dir / "err.0") && test::read_file(dir / "err.0").find(" 10% ") != std::string::npos)
      signalled = ::kill(pid_t(std::stol(test::read_file(dir / "pid.1"))), SIGTERM) == 0;
  }
  const auto r = stopped.get();
  ASSERT_TRUE(signalled) << "the run ended before rank 0 reported 10 %: " << r.err;
  EXPECT_EQ(r.exit_status, 143) << r.err;
  const std::string err = test::read_file(dir / "err.0") + test::read_file(dir / "err.1");
  EXPECT_NE(err.find("c.h5 holds step "), std::string::npos) << err;
  EXPECT_NE(err.find("error: interrupted by SIGTERM after "), std::string::npos) << err;
  EXPECT_NE(err.find("; kept " + (dir / "c.h5").string() + " (a checkpoint at step "), std::string::npos) << err;
  EXPECT_EQ(occurrences(err, "error: "), 1u) << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.h5"));
  const auto runs = recorded_runs(dir / "p.sqlite");
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].exit_status, 143);
  EXPECT_EQ(runs[0].params.value("mpi_rank", -1), 0);
  const auto again = mpirun(3, with(base, {"--quiet", "--signals", (dir / "s.h5").string(), "--restart", (dir / "c.h5").string()}));
  ASSERT_EQ(again.exit_status, 0) << again.err;
  EXPECT_EQ(test::read_file(dir / "one.h5"), test::read_file(dir / "s.h5"));  // cmp: the same bytes
}

// What a distributed run does not do: one line, exit 1, nothing written.
TEST(MwDemMpi, OneProcessOptionsAndMoreRanksThanSphereBlocksAreRefusedInOneLine) {
  test::TempDir dir;
  write_block(dir);
  test::write_file(dir / "wave.toml", wave_scene(dir / "block.h5"));
  const auto refused = mpirun(2, {"run", (dir / "wave.toml").string(), "--quiet", "--signals-pattern", (dir / "s-{f}.h5").string(),
                               "--frequencies-kHz", "100,200", "--db", (dir / "p.sqlite").string()});
  EXPECT_EQ(refused.exit_status, 1);
  EXPECT_NE(refused.err.find("--frequencies-kHz"), std::string::npos) << refused.err;
  // Every rank fails alike: one record, rank 0's.
  const auto refused_runs = recorded_runs(dir / "p.sqlite");
  ASSERT_EQ(refused_runs.size(), 1u);
  EXPECT_EQ(refused_runs[0].exit_status, 1);
  EXPECT_EQ(refused_runs[0].params.value("mpi_rank", -1), 0);
  const auto many = mpirun(5, {"run", (dir / "wave.toml").string(), "--quiet", "--model", "linear", "--signals",
                               (dir / "s.h5").string()});
  EXPECT_EQ(many.exit_status, 1);
  EXPECT_NE(many.err.find("5 MPI ranks for 864 spheres"), std::string::npos) << many.err;
  EXPECT_EQ(occurrences(many.err, "error: "), 1u) << many.err;  // every rank fails alike: printed once
  EXPECT_EQ(occurrences(refused.err, "error: "), 1u) << refused.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.h5"));
  EXPECT_FALSE(std::filesystem::exists(dir / "s-100.h5"));
}

// A contact whose other end is on another rank needs that end as a ghost; the test-only hook
// keeps on rank 1 only ghosts closer than 1 um to their contact's own end (none: the spheres are
// about a millimetre apart), so every cross-rank bond there loses its partner. Rank 1 alone fails,
// at setup, while rank 0 waits in the first exchange: the run must still end at once, with one
// line naming a bond and the rank, exit 1 and no output - never a run with bonds silently lost.
TEST(MwDemMpi, ABondWhosePartnerIsNotAGhostEndsEveryRankWithOneLineNamingTheBondAndTheRank) {
  test::TempDir dir;
  write_block(dir);
  test::write_file(dir / "wave.toml", wave_scene(dir / "block.h5"));
  const auto r = mpirun(2, {"run", (dir / "wave.toml").string(), "--quiet", "--model", "linear", "--signals", (dir / "s.h5").string(),
                            "--db", (dir / "p.sqlite").string()},
                        {"MESOWAVE_TEST_GHOST_LAYER_MM=0.001", "MESOWAVE_TEST_GHOST_LAYER_RANK=1"});
  EXPECT_EQ(r.exit_status, 1) << r.err;  // not 124: rank 0 did not hang
  EXPECT_NE(r.err.find("error: rank 1 of 2: bond "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("has lost its partner"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ghost layer 0.001 mm"), std::string::npos) << r.err;
  EXPECT_EQ(occurrences(r.err, "error: "), 1u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.h5"));
  // Only rank 1 saw it, so rank 1 recorded it: what was tried is in mw-prov runs.
  const auto runs = recorded_runs(dir / "p.sqlite");
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].exit_status, 1);
  EXPECT_NE(runs[0].error.find("rank 1 of 2: bond "), std::string::npos) << runs[0].error;
  EXPECT_EQ(runs[0].params.value("mpi_rank", -1), 1);
}
