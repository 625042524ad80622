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

TEST(QuantityFile, ForeignKeysAreADeclarationNotAnEntry) {
  const auto toml = io::parse_quantity_document(
      "foreign_keys = [\"hold\"]\n[hold]\nvalue = 20.0\nunit = \"s\"\nsource = \"paper\"\ncite = \"s\"\n"
      "[gauge_length]\nvalue = 75.0\nunit = \"mm\"\nsource = \"paper\"\ncite = \"s\"\n",
      "lab.toml");
  ASSERT_EQ(toml.quantities.size(), 2u);
  EXPECT_EQ(toml.foreign_keys, std::vector<std::string>{"hold"});
  const auto json = io::parse_quantity_document(R"({"E_dem_GPa": 30, "E_glob_GPa": 31, "foreign_keys": ["E_glob_GPa"]})", "c.json");
  ASSERT_EQ(json.quantities.size(), 2u);
  EXPECT_EQ(json.foreign_keys, std::vector<std::string>{"E_glob_GPa"});
  EXPECT_TRUE(io::parse_quantity_document(R"({"E_d_GPa": 36})", "o.json").foreign_keys.empty());
  // The readers that take every entry (mw-compare, mw-table) do not see the declaration.
  EXPECT_EQ(io::parse_quantity_text(R"({"a": 1, "foreign_keys": ["a"]})", "o.json").size(), 1u);
}

TEST(QuantityFile, AForeignKeysDeclarationMustNameEntries) {
  EXPECT_THROW(io::parse_quantity_document("foreign_keys = \"hold\"\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_document("foreign_keys = [1]\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_document("foreign_keys = [\"hold\"]\n", "a.toml"), InputError);
  EXPECT_THROW(io::parse_quantity_document(R"({"a": 1, "foreign_keys": "a"})", "a.json"), InputError);
  EXPECT_THROW(io::parse_quantity_document(R"({"a": 1, "foreign_keys": ["b"]})", "a.json"), InputError);
}
