#include <gtest/gtest.h>

#include "mesowave/core/error.hpp"
#include "mesowave/io/quantity_file.hpp"

using namespace mesowave;

TEST(QuantityFile, TomlEntriesBecomeOptionNames) {
  const auto q = io::parse_quantity_text(
      "[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"paper\"\ncite = \"Section 3.2\"\n"
      "[nu_st]\nvalue = 0.16\nunit = \"\"\nsource = \"assumed\"\ncite = \"equal to nu_d\"\n"
      "[shape]\nvalue = \"cube\"\nsource = \"synthetic\"\n",
      "lab.toml");
  ASSERT_EQ(q.size(), 3u);
  EXPECT_EQ(q[0].option_name(), "t-p-us");
  EXPECT_EQ(q[0].value, "35");
  EXPECT_EQ(q[1].option_name(), "nu-st");
  EXPECT_EQ(q[2].value, "cube");
}

TEST(QuantityFile, JsonKeysAlreadyCarryTheirUnit) {
  const auto q = io::parse_quantity_text(R"({"E_d_GPa": 36.671373808399046, "method": "Eq. 9", "list": [1]})", "o.json");
  ASSERT_EQ(q.size(), 2u);
  EXPECT_EQ(q[0].option_name(), "E-d-GPa");
  EXPECT_EQ(std::stod(q[0].value), 36.671373808399046);  // round-trips exactly
}

TEST(QuantityFile, EveryLabValueMustSayWhereItComesFrom) {
  EXPECT_THROW(io::parse_quantity_text("[x]\nvalue = 1\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_text("[x]\nvalue = 1\nsource = \"measured\"\ncite = \"?\"\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_text("[x]\nvalue = 1\nsource = \"paper\"\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_text("[x]\nsource = \"synthetic\"\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_text("x = 1\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_text("[x\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_text("{broken", "a.json"), InputError);
}

// scripts/new-study marks every copied value a placeholder; it still says where it came from.
TEST(QuantityFile, APlaceholderCopiedByNewStudyReadsButMustCiteItsOrigin) {
  const auto q = io::parse_quantity_text(
      "[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"placeholder\"\ncite = \"copied from concrete-cube (paper)\"\n",
      "upv.toml");
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q[0].source, "placeholder");
  EXPECT_THROW(io::parse_quantity_text("[t_p]\nvalue = 35.0\nunit = \"us\"\nsource = \"placeholder\"\n", "upv.toml"),
               InputError);
}
