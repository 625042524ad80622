// MTS 793 text exports read as laboratories hand them over: Latin-1, tabs,
// decimal commas, operator header, several data blocks.
#include <gtest/gtest.h>

#include <cmath>

#include "mesowave/core/error.hpp"
#include "mesowave/io/mts_export.hpp"
#include "support/input_error.hpp"

using namespace mesowave;

namespace {

// A small export in the layout of the BAM files: header with umlauts (Latin-1
// bytes \xe4 \xf6), a time series with an empty field, a two-row summary.
const std::string kExport =
    "MTS793|MPT|DEU|1|2|,|.|:|49|1|1|A\r\n"
    "\r\n"
    "Bediener Information\t\t\tW\xfcrfeldruckfestigkeit (150mm)\t\t\tZeit:\t71,0\ts\t28.01.2015 10:33:47\r\n"
    "Durchmesser [mm]:\t98,6\r\n"
    "L\xe4nge :\t300,2\r\n"
    "Bediener Information Ende\r\n"
    "\r\n"
    "Datenerfassung\t\t\t\t\t\tZeit:\t387,0752\ts\t01.09.2014 14:36:18\r\n"
    "Laufzeit\tCh 1 Kraft\t1944 B\r\n"
    "s\tkN\tmm\r\n"
    "16,5\t-1,25\t0,001\r\n"
    "17,0\t-2,5\t\r\n"
    "17,5\t-3,75\t-0,002\r\n"
    "\r\n"
    "Datenerfassung\t\t\t\t\t\tZeit:\t387,08\ts\t01.09.2014 14:36:18\r\n"
    "Ch 1 Kraft\t1944 B\r\n"
    "kN\tmm\r\n"
    "0,5\t0,01\r\n"
    "-3,75\t-0,002\r\n";

}  // namespace

TEST(MtsExport, ReadsLatin1DecimalCommasAndBlocks) {
  const auto mts = io::parse_mts_export(kExport, "test.dat");
  EXPECT_EQ(mts.decimal_separator, ',');
  ASSERT_EQ(mts.blocks.size(), 2u);
  const auto& b = mts.blocks[0];
  EXPECT_EQ(b.names, (std::vector<std::string>{"Laufzeit", "Ch 1 Kraft", "1944 B"}));
  EXPECT_EQ(b.units, (std::vector<std::string>{"s", "kN", "mm"}));
  ASSERT_EQ(b.rows(), 3u);
  EXPECT_DOUBLE_EQ(b.columns[0][1], 17.0);
  EXPECT_DOUBLE_EQ(b.columns[1][2], -3.75);
  EXPECT_TRUE(std::isnan(b.columns[2][1]));  // empty field: no reading
  EXPECT_EQ(mts.blocks[1].rows(), 2u);
  EXPECT_DOUBLE_EQ(*mts.header_number("Durchmesser"), 98.6);
  EXPECT_DOUBLE_EQ(*mts.header_number("Länge"), 300.2);  // Latin-1 converted to UTF-8
  EXPECT_EQ(*mts.header_text("Bemerkung"), "Würfeldruckfestigkeit (150mm)");
}

TEST(MtsExport, RefusesMalformedFiles) {
  EXPECT_THROW(io::parse_mts_export("t_s,force_kN\n1,2\n", "x.csv"), InputError);
  std::string bad = kExport;
  bad.replace(bad.find("-2,5"), 4, "-2x5");
  const std::string error = mesowave::test::input_error_of([&] { io::parse_mts_export(bad, "bad.dat"); });
  EXPECT_NE(error.find("bad.dat:12"), std::string::npos) << error;
}
