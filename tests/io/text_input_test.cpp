// The shared number parser every text reader uses: a field is a number only if all of it is
// one finite decimal number (issue 18, finding 1).
#include "molmesh/io/text_input.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include "io/io_test_support.hpp"

namespace molmesh {
namespace {

using io_detail::parse_double;
using io_detail::parse_integer;
using io_detail::split_fields;
using io_detail::trim;

// One definition of blank for trim and split_fields (issue 18): trim kept \v and \f while
// split_fields treated them as separators, and split_fields kept \r inside a field.
TEST(TextInput, TrimAndSplitFieldsShareOneBlankSet) {
  EXPECT_EQ(trim("\v\f x \r\n"), "x");
  EXPECT_EQ(split_fields("a\rb\vc"), (std::vector<std::string_view>{"a", "b", "c"}));
  EXPECT_EQ(split_fields("a,\fb", true), (std::vector<std::string_view>{"a", "b"}));
  // The set is the C locale's isspace (tests run in the C locale), byte by byte; a line of
  // any of them trims to nothing and has no fields.
  for (int c = 0; c < 256; ++c) {
    const char ch = static_cast<char>(c);
    EXPECT_EQ(io_detail::is_blank(ch), std::isspace(c) != 0) << "byte " << c;
    if (!io_detail::is_blank(ch)) continue;
    const std::string line(3, ch);
    EXPECT_TRUE(trim(line).empty()) << "byte " << c;
    EXPECT_TRUE(split_fields(line).empty()) << "byte " << c;
  }
}

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
