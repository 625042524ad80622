// scripts/install-deps, the first step of `make test` and `make reproduce`:
// on a machine without the -dev packages it must ask apt-get for exactly the
// missing ones, and on a machine that has them all it must not call apt-get.
// The packages of this machine cannot be removed for a test, so dpkg, apt-get,
// id and sudo are replaced by shims on PATH that answer from a list and record
// every call.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_tool.hpp"

using namespace mesowave::test;
namespace fs = std::filesystem;

namespace {

// The packages CMakeLists.txt finds (its find_package lines) and the tools to build with.
const std::vector<std::string> kBuildPackages = {
    "build-essential", "cmake",        "pkg-config",   "libeigen3-dev", "libsqlite3-dev",      "libhdf5-dev",
    "libfftw3-dev",    "libcli11-dev", "libgtest-dev", "libpng-dev",    "libtomlplusplus-dev", "nlohmann-json3-dev",
    "libtiff-dev",     "libssl-dev",   "libopenmpi-dev"};

class Shims {
public:
  // `missing`: packages dpkg -s reports as not installed; `uid`: what id -u prints.
  Shims(const std::vector<std::string>& missing, int uid, bool apt_fails_first = false) {
    std::string list;
    for (const auto& p : missing) list += p + "\n";
    write_file(dir_ / "missing", list);
    if (apt_fails_first) write_file(dir_ / "fail-first", "");
    const std::string d = dir_.path().string();
    script("dpkg", "echo \"$2\" >> " + d + "/queried\n"
                   "[ \"$1\" = -s ] || exit 2\n"
                   "grep -qx -- \"$2\" " + d + "/missing && exit 1\n"
                   "exit 0\n");
    script("apt-get", "echo \"DEBIAN_FRONTEND=$DEBIAN_FRONTEND apt-get $*\" >> " + d + "/calls\n"
                      "if [ \"$1\" = install ] && [ -e " + d + "/fail-first ]; then rm " + d + "/fail-first; exit 100; fi\n"
                      "exit 0\n");
    script("id", "echo " + std::to_string(uid) + "\n");
    // Like sudo's default env_reset: the caller's environment does not pass.
    script("sudo", "echo sudo >> " + d + "/calls\nexec env -i PATH=\"$PATH\" \"$@\"\n");
  }

  ToolResult run(const std::vector<std::string>& args = {}) const {
    const fs::path install_deps = fs::path(MESOWAVE_SOURCE_DIR) / "scripts/install-deps";
    std::vector<std::string> command = {"PATH=" + dir_.path().string() + ":/usr/bin:/bin", "bash", install_deps.string()};
    command.insert(command.end(), args.begin(), args.end());
    return run_command("/usr/bin/env", command);
  }

  std::vector<std::string> lines(const std::string& name) const {
    std::vector<std::string> out;
    if (!fs::exists(dir_ / name)) return out;
    std::istringstream in(read_file(dir_ / name));
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  }

private:
  void script(const std::string& name, const std::string& body) {
    write_file(dir_ / name, "#!/bin/sh\n" + body);
    fs::permissions(dir_ / name, fs::perms::owner_all);
  }
  TempDir dir_;
};

}  // namespace

TEST(InstallDeps, AMachineWithEverythingPaysNothing) {
  const Shims shims({}, 0);
  const auto r = shims.run();
  EXPECT_EQ(r.exit_status, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(shims.lines("calls").empty());
  // Every package the build needs was asked about.
  const auto queried = shims.lines("queried");
  for (const auto& p : kBuildPackages)
    EXPECT_NE(std::find(queried.begin(), queried.end(), p), queried.end()) << p << " is not checked";
}

TEST(InstallDeps, AbsentDevPackagesAreInstalledAndOnlyThose) {
  const Shims shims({"libfftw3-dev", "libgtest-dev", "libhdf5-dev"}, 0);
  const auto r = shims.run();
  ASSERT_EQ(r.exit_status, 0) << r.err;
  EXPECT_NE(r.out.find("installing libhdf5-dev libfftw3-dev libgtest-dev"), std::string::npos) << r.out;
  const auto calls = shims.lines("calls");
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0],
            "DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends libhdf5-dev libfftw3-dev libgtest-dev");
}

TEST(InstallDeps, AStalePackageIndexIsRefreshedOnce) {
  const Shims shims({"libeigen3-dev"}, 0, /*apt_fails_first=*/true);
  const auto r = shims.run();
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto calls = shims.lines("calls");
  ASSERT_EQ(calls.size(), 3u);
  EXPECT_NE(calls[0].find("apt-get install -y --no-install-recommends libeigen3-dev"), std::string::npos);
  EXPECT_NE(calls[1].find("apt-get update"), std::string::npos);
  EXPECT_NE(calls[2].find("apt-get install -y --no-install-recommends libeigen3-dev"), std::string::npos);
}

TEST(InstallDeps, AnOrdinaryUserInstallsThroughSudo) {
  const Shims shims({"libcli11-dev"}, 1000);
  const auto r = shims.run();
  ASSERT_EQ(r.exit_status, 0) << r.err;
  const auto calls = shims.lines("calls");
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(calls[0], "sudo");
  // sudo resets the environment: apt-get must still run without questions.
  EXPECT_EQ(calls[1], "DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends libcli11-dev");
}

// `make fuzz` needs clang and libFuzzer (scripts/install-deps fuzz); `make test` must not.
TEST(InstallDeps, ClangOnlyForTheFuzzBuild) {
  const Shims shims({"clang", "libclang-rt-14-dev"}, 0);
  const auto plain = shims.run();
  ASSERT_EQ(plain.exit_status, 0) << plain.err;
  EXPECT_TRUE(shims.lines("calls").empty()) << "the normal build asked for clang";
  const auto fuzz = shims.run({"fuzz"});
  ASSERT_EQ(fuzz.exit_status, 0) << fuzz.err;
  const auto calls = shims.lines("calls");
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0], "DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends clang libclang-rt-14-dev");
}

// The suite's Slurm test needs slurm-wlm and munge (scripts/install-deps slurm, which `make test`
// runs); the build and `make reproduce` do not.
TEST(InstallDeps, SlurmOnlyForTheSlurmGroup) {
  const Shims shims({"slurm-wlm", "munge"}, 0);
  const auto plain = shims.run();
  ASSERT_EQ(plain.exit_status, 0) << plain.err;
  EXPECT_TRUE(shims.lines("calls").empty()) << "the normal build asked for Slurm";
  const auto slurm = shims.run({"slurm"});
  ASSERT_EQ(slurm.exit_status, 0) << slurm.err;
  const auto calls = shims.lines("calls");
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(calls[0], "DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends slurm-wlm munge");
}
