#include "molmesh/core/error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace molmesh {
namespace {

std::string flags(std::string_view name) {
  if (name == "size_factor") return "--size-factor";
  if (name == "max_levels") return "--levels";
  return "";
}

TEST(SpellOptionNames, BackquotedNamesTakeTheFrontEndsSpelling) {
  EXPECT_EQ(spell_option_names("raise `size_factor` (at `size_factor` 0.1)", flags),
            "raise --size-factor (at --size-factor 0.1)");
  EXPECT_EQ(spell_option_names("`max_levels` must not be negative", flags),
            "--levels must not be negative");
}

TEST(SpellOptionNames, UnknownNamesAndOtherBackquotesStayAsTheyAre) {
  EXPECT_EQ(spell_option_names("`spacing` too fine", flags), "`spacing` too fine");
  EXPECT_EQ(spell_option_names("a ` lone backquote, `` and `two words`", flags),
            "a ` lone backquote, `` and `two words`");
  EXPECT_EQ(spell_option_names("ends with `size_factor", flags), "ends with `size_factor");
  EXPECT_EQ(spell_option_names("", flags), "");
  EXPECT_EQ(spell_option_names("no names", flags), "no names");
}

}  // namespace
}  // namespace molmesh
