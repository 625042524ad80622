// LAUNCH=slurm (issue 18 item 4) on a one-node Slurm cluster that the check starts on localhost
// (munged, slurmctld, slurmd; slurm.conf and the MUNGE key written in a temporary folder, the
// daemons stopped at the end): the steel-rod study of the quick pipeline, run plainly and through
// Slurm in two copies of the tree (scripts/check-slurm steel-rod-summary). Every tool line was a
// Slurm job that completed; the outputs are byte for byte equal, or value by value with the wall
// times aside for the files that carry them; the two provenance databases hold the same runs,
// files and metrics, every run of the Slurm one merged from a step's database, none twice.
// `make check-slurm` runs the whole of reproduce-quick the same way (docs/slurm.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include "support/run_tool.hpp"

using namespace mesowave::test;
namespace fs = std::filesystem;

TEST(Pipeline, SteelRodThroughSlurmGivesThePlainResultsAndWholeProvenance) {
  if (::geteuid() != 0) GTEST_SKIP() << "the Slurm daemons need root (this test starts munged, slurmctld, slurmd)";
  for (const char* program : {"/usr/sbin/munged", "/usr/sbin/slurmctld", "/usr/sbin/slurmd", "/usr/bin/srun"})
    if (!fs::exists(program)) GTEST_SKIP() << program << " is missing: scripts/install-deps slurm (make test runs it)";
  const fs::path source = MESOWAVE_SOURCE_DIR, build = fs::path(MESOWAVE_BIN_DIR).parent_path();
  const auto r = run_command(source / "scripts/check-slurm", {"--build", build.string(), "-j", "2", "steel-rod-summary"});
  EXPECT_EQ(r.exit_status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("check-slurm: all hold"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(r.out.find("FAILED"), std::string::npos) << r.out;
  std::cout << r.out;  // the counts: jobs, files compared, provenance rows
}
