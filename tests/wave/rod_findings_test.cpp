// The rod paper's findings checked on a study's tables (wave/rod_findings): on
// the quick pipeline's numbers the check list reads as the shell script that
// wrote it before (pipeline/steel-rod/summarize.sh at 5a586c5, awk and sort -g)
// printed it, and each finding turns on its own rule.
#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/io/csv.hpp"
#include "mesowave/wave/rod_findings.hpp"
#include "support/input_error.hpp"

using namespace mesowave;

namespace {

const char* kVelocity =
    "f_kHz,theory,FEM 1 mm,0.95R,1.03R,1.05R,1.15R,0.95R-EDEM\n"
    "50,5121.6,5103.2,2864.1,5152.2,5109.3,5171.4,5056.0\n"
    "100,5004.0,4995.1,2563.2,4943.4,4892.5,4898.6,4875.1\n"
    "150,4751.4,4712.3,2107.4,4629.8,4566.0,4525.2,4597.3\n";
const char* kTable1 =
    "model,pcc_vs_fem_signal,pcc_vs_fem_envelope,paper_pcc_vs_fem\n"
    "0.95R,-0.053,-0.145,-0.012\n1.03R,0.486,0.961,0.892\n1.05R,0.595,0.931,0.886\n1.15R,0.150,0.910,0.860\n"
    "0.95R-EDEM,0.197,0.920,\n";
const char* kTable2 =
    "model,rss_m2_s2,rms_m_s,paper_rss_m2_s2\n"
    "FEM 1 mm,1993,25.8,6056\n0.95R,18051666,2453,11694645\n1.03R,19398,80.4,22436\n1.05R,47099,125.3,61084\n"
    "1.15R,64919,147.1,\n0.95R-EDEM,45044,122.5,\n";

io::CsvTable csv(const std::string& text) { return io::parse_csv(text, "t.csv"); }

}  // namespace

TEST(RodFindings, TheQuickPipelinesChecklistAsTheScriptPrintedIt) {
  const auto f = wave::rod_findings(csv(kVelocity), csv(kTable1), csv(kTable2), "FEM 1 mm");
  EXPECT_EQ(f.markdown(),
            "- [x] velocity falls with frequency (c_g at 150 kHz below 50 kHz for the FEM and the 1.03R, 1.05R, 1.15R "
            "chains)\n"
            "- [x] 0.95R is the outlier: largest RSS (0.95R) and lowest PCC against the FEM (0.95R)\n"
            "- [x] 1.03R is closest to theory and FEM among 1.03R, 1.05R, 1.15R (lowest RSS: 1.03R; highest PCC: "
            "1.03R)\n"
            "- [ ] denser spacing gives a higher group velocity: c_g(1.03R) > c_g(1.05R) > c_g(1.15R) at 1 of 3 "
            "frequencies (NOT reproduced)\n"
            "  - 1.03R faster than 1.05R at 3 of 3 frequencies; 1.05R faster than 1.15R at 1 of 3 (from 150 kHz up).\n");
}

TEST(RodFindings, EachFindingTurnsOnItsOwnRule) {
  // The FEM rising with frequency fails finding 1 alone.
  std::string rising = kVelocity;
  rising.replace(rising.find("4712.3"), 6, "5200.0");
  auto f = wave::rod_findings(csv(rising), csv(kTable1), csv(kTable2), "FEM 1 mm");
  EXPECT_FALSE(f.velocity_falls);
  EXPECT_EQ(f.largest_rss, "0.95R");
  // 1.15R with the largest RSS; 1.05R with the best PCC of the usable three.
  std::string t2 = kTable2;
  t2.replace(t2.find("64919"), 5, "99999999");
  std::string t1 = kTable1;
  t1.replace(t1.find("0.931"), 5, "0.990");
  f = wave::rod_findings(csv(kVelocity), csv(t1), csv(t2), "FEM 1 mm");
  EXPECT_EQ(f.largest_rss, "1.15R");
  EXPECT_EQ(f.lowest_pcc, "0.95R");
  EXPECT_EQ(f.best_rss, "1.03R");
  EXPECT_EQ(f.best_pcc, "1.05R");
  EXPECT_NE(f.markdown().find("- [ ] 0.95R is the outlier: largest RSS (1.15R)"), std::string::npos);
  // A tie goes to the name sort -g puts last (largest) or first (smallest).
  t2 = kTable2;
  t2.replace(t2.find("47099"), 5, "19398");
  EXPECT_EQ(wave::rod_findings(csv(kVelocity), csv(kTable1), csv(t2), "FEM 1 mm").best_rss, "1.03R");
  // Ordered at every frequency, and the run of 1.05R > 1.15R broken in the middle.
  const auto ordered = csv("f_kHz,FEM,1.03R,1.05R,1.15R\n50,3,3,2,1\n100,2,3,2,1\n150,1,3,2,1\n");
  f = wave::rod_findings(ordered, csv(kTable1), csv(kTable2), "FEM");
  EXPECT_EQ(f.ordered, 3);
  EXPECT_EQ(f.faster_105_115_from_kHz, "50");
  EXPECT_NE(f.markdown().find("- [x] denser spacing"), std::string::npos);
  const auto broken = csv("f_kHz,FEM,1.03R,1.05R,1.15R\n50,3,3,2,1\n100,2,3,2,3\n150,1,3,2,1\n");
  f = wave::rod_findings(broken, csv(kTable1), csv(kTable2), "FEM");
  EXPECT_EQ(f.faster_105_115, 2);
  EXPECT_EQ(f.faster_105_115_from_kHz, "150");
}

TEST(RodFindings, MissingModelsAndShortTablesAreErrors) {
  EXPECT_EQ(test::input_error_of([] {
              wave::rod_findings(csv("f_kHz,FEM,1.03R,1.05R,1.15R\n50,3,3,2,1\n"), csv(kTable1), csv(kTable2), "FEM");
            }),
            "t.csv: the findings need at least two frequencies, it has 1");
  EXPECT_EQ(test::input_error_of(
                [] { wave::rod_findings(csv(kVelocity), csv(kTable1), csv("model,rss_m2_s2\n1.03R,1\n"), "FEM 1 mm"); }),
            "t.csv has no row for 0.95R");
  EXPECT_NE(test::input_error_of([] { wave::rod_findings(csv(kVelocity), csv(kTable1), csv(kTable2), "FEM 2 mm"); })
                .find("missing column 'FEM 2 mm'"),
            std::string::npos);
}
