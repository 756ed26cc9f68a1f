// The shared number parser every text reader uses: a field is a number only if all of it is
// one finite decimal number (issue 18, finding 1).
#include "molmesh/io/text_input.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/io_test_support.hpp"

namespace molmesh {
namespace {

using io_detail::parse_double;
using io_detail::parse_integer;

TEST(TextInput, ParseDoubleTakesWholeFiniteDecimalFieldsOnly) {
  EXPECT_EQ(parse_double("1.5"), 1.5);
  EXPECT_EQ(parse_double("+2"), 2.0);
  EXPECT_EQ(parse_double("-1e-5"), -1e-5);
  EXPECT_EQ(parse_double(".5"), 0.5);
  EXPECT_EQ(parse_double("3."), 3.0);
  for (const char* bad : {"",     "+",        "++1",    "+-1",  "abc", "1.5abc", "1,5",
                          "0x10", "1e400",    "-1e400", "nan",  "NaN", "-nan",   "inf",
                          "-inf", "infinity", "1.5 ",   " 1.5", "1e",  "--1",    "1..2"})
    EXPECT_FALSE(parse_double(bad).has_value()) << "'" << bad << "' was read as a number";
}

TEST(TextInput, ParseIntegerTakesWholeFieldsOnly) {
  EXPECT_EQ(parse_integer("42"), 42);
  EXPECT_EQ(parse_integer("+7"), 7);
  EXPECT_EQ(parse_integer("-3"), -3);
  for (const char* bad : {"", "+", "1.0", "0x10", "1e3", "12a", "99999999999999999999", "+-1"})
    EXPECT_FALSE(parse_integer(bad).has_value()) << "'" << bad << "' was read as an integer";
}

TEST(TextInput, RequireDoubleNamesFileLineAndField) {
  test::expect_input_error([] { io_detail::require_double("1,5", "charge", "a.txt", 7); },
                           {"a.txt:7: charge '1,5' is not a finite number"});
  // Long tokens are cut in the message.
  test::expect_input_error(
      [] { io_detail::require_double(std::string(5000, 'x'), "x", "a.txt", 1); },
      {"(5000 characters)"});
}

TEST(TextInput, MessagesEscapeControlBytesInsteadOfStoppingAtThem) {
  const InputError e("f.pdb", 3, std::string("field 'a\0b\rc\x1b[2J'", 17));
  const std::string what = e.what();
  EXPECT_EQ(what, "f.pdb:3: field 'a\\x00b\\x0dc\\x1b[2J'");
}

TEST(TextInput, RequireNoNulNamesTheLine) {
  EXPECT_NO_THROW(io_detail::require_no_nul("a\nb\n", "t.txt"));
  test::expect_input_error(
      [] { io_detail::require_no_nul(std::string("a\nb\nc\0d\n", 8), "t.txt"); },
      {"t.txt:3:", "NUL byte"});
}

}  // namespace
}  // namespace molmesh
