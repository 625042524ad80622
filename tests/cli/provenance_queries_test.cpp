// mw-prov's questions on a small recorded history: diff, verify, metrics, why, export.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_tool.hpp"

using namespace mesowave::test;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// What mw-upv's JSON carries besides what mw-estatic takes (E_d_GPa, density_kg_m3).
const std::string kUpvJsonUntaken = "G_d_GPa,method,nu_d,nu_d_source,path_mm,t_p_us,t_s_us,v_p_m_s,v_s_m_s";

struct RecordedHistory : ::testing::Test {
  TempDir dir;
  std::string db = (dir / "p.sqlite").string();
  std::vector<std::string> upv(const std::string& t_p_us) {
    return {"--path-mm", "150", "--t-p-us", t_p_us, "--t-s-us", "55.1", "--density-kg-m3", "2129.56",
            "--out", (dir / "upv.json").string(), "--db", db};
  }
  json prov(std::vector<std::string> args) {
    args.insert(args.begin(), {"--db", db});
    args.push_back("--json");
    const auto r = run_tool("mw-prov", args);
    EXPECT_EQ(r.exit_status, 0) << r.err;
    return json::parse(r.out);
  }
  void SetUp() override {
    ASSERT_EQ(run_tool("mw-upv", upv("35")).exit_status, 0);                             // run 1
    ASSERT_EQ(run_tool("mw-estatic", {"--from", (dir / "upv.json").string(), "--table", (dir / "t1.csv").string(),
                                      "--db", db, "--from-ignore", kUpvJsonUntaken})
                  .exit_status,
              0);                                                                        // run 2
  }
};

}  // namespace

TEST_F(RecordedHistory, DiffNamesTheParameterOutputAndMetricsThatDiffer) {
  ASSERT_EQ(run_tool("mw-upv", upv("36")).exit_status, 0);  // run 3
  const auto d = prov({"diff", "1", "3"});
  ASSERT_EQ(d["params"].size(), 1u);
  EXPECT_EQ(d["params"][0]["key"], "t-p-us");
  EXPECT_EQ(d["inputs"].size(), 0u);
  EXPECT_EQ(d["outputs"].size(), 1u);
  std::set<std::string> metrics;
  for (const auto& m : d["metrics"]) metrics.insert(m["key"]);
  EXPECT_EQ(metrics, (std::set<std::string>{"E_d", "nu_d", "v_p"}));  // v_s depends on t_s only
  EXPECT_NE(run_tool("mw-prov", {"--db", db, "diff", "1", "1"}).out.find("do not differ"), std::string::npos);
}

TEST_F(RecordedHistory, VerifyFindsChangedAndMissingOutputs) {
  for (const auto& c : prov({"verify"})) EXPECT_EQ(c["state"], "unchanged");
  write_file(dir / "t1.csv", "tampered\n");
  fs::remove(dir / "upv.json");
  std::map<std::string, std::string> state;
  for (const auto& c : prov({"verify"})) state[fs::path(c["path"].get<std::string>()).filename()] = c["state"];
  EXPECT_EQ(state["t1.csv"], "changed");
  EXPECT_EQ(state["upv.json"], "missing");
}

TEST_F(RecordedHistory, MetricsAcrossRunsBesideAParameter) {
  ASSERT_EQ(run_tool("mw-upv", upv("36")).exit_status, 0);
  const auto rows = prov({"metrics", "E_d", "--by", "t-p-us"});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["t-p-us"], "35.0");
  EXPECT_EQ(rows[1]["t-p-us"], "36.0");
  // E_d scales as 1/t_s^2 only through v_s, and nu_d through (t_s/t_p)^2: check against Eqs. 9-10 by hand.
  const double r2 = (55.1 / 36) * (55.1 / 36), nu = (0.5 * r2 - 1) / (r2 - 1), vs = 0.15 / 55.1e-6;
  EXPECT_NEAR(rows[1]["value"].get<double>(), 2 * 2129.56 * vs * vs * (1 + nu) / 1e9, 1e-9);
}

TEST_F(RecordedHistory, WhySaysWhichUpstreamFileChanged) {
  EXPECT_TRUE(prov({"why", (dir / "t1.csv").string()})["up_to_date"].get<bool>());
  ASSERT_EQ(run_tool("mw-upv", upv("36")).exit_status, 0);  // upv.json changes; t1.csv is now out of date
  const auto w = prov({"why", (dir / "t1.csv").string()});
  EXPECT_FALSE(w["up_to_date"].get<bool>());
  ASSERT_EQ(w["changed"].size(), 1u);
  EXPECT_EQ(fs::path(w["changed"][0]["path"].get<std::string>()).filename(), "upv.json");
  EXPECT_EQ(w["changed"][0]["read_by"]["tool"], "mw-estatic");
}

TEST_F(RecordedHistory, ExportIsValidProvJson) {
  const auto r = run_tool("mw-prov", {"--db", db, "export", "--format", "prov-json"});
  ASSERT_EQ(r.exit_status, 0) << r.err;
  write_file(dir / "prov.json", r.out);
  const auto doc = json::parse(r.out);
  EXPECT_EQ(doc["activity"].size(), 2u);
  EXPECT_EQ(doc["used"].size(), 1u);            // mw-estatic read upv.json
  EXPECT_EQ(doc["wasGeneratedBy"].size(), 2u);  // upv.json and t1.csv
  // Independent check: the W3C PROV reference library for Python and a JSON schema.
  const auto v = run_command(fs::path(MESOWAVE_SOURCE_DIR) / "scripts/validate-prov-json", {(dir / "prov.json").string()});
  EXPECT_EQ(v.exit_status, 0) << v.out << v.err;
  EXPECT_EQ(v.out.rfind("valid PROV-JSON", 0), 0u) << v.out;
  // ...and it can fail: a dangling reference is caught.
  auto broken = doc;
  broken["used"]["_:u1"]["prov:entity"] = "mw:file-nothing";
  write_file(dir / "broken.json", broken.dump());
  EXPECT_EQ(run_command(fs::path(MESOWAVE_SOURCE_DIR) / "scripts/validate-prov-json", {(dir / "broken.json").string()})
                .exit_status,
            1);
  const auto dot = run_tool("mw-prov", {"--db", db, "export", "--format", "dot"});
  EXPECT_EQ(dot.out.rfind("digraph provenance", 0), 0u);
}
