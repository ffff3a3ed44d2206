// parse_integer and parse_real (mesh/io/text_lines.hpp), the numbers of every
// text reader: a whole token or nothing, a leading '+' allowed, decimal only,
// values that do not fit refused, "nan" and "inf" left to the caller.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>

#include "mesh/io/text_lines.hpp"

namespace tetsmooth {
namespace {

// What parse_integer reads from `token`; nothing when it refuses it.
std::optional<long long> integer(std::string_view token) {
  long long value = 0;
  if (!parse_integer(token, value)) return std::nullopt;
  return value;
}

// What parse_real reads from `token`; nothing when it refuses it.
std::optional<double> real(std::string_view token) {
  double value = 0;
  if (!parse_real(token, value)) return std::nullopt;
  return value;
}

std::uint64_t bits(double value) {
  std::uint64_t b = 0;
  std::memcpy(&b, &value, sizeof b);
  return b;
}

// Tokens that look like numbers to a person but are not whole numbers to
// either function: empty, a sign alone, blanks, two signs, trailing junk.
constexpr std::string_view kNotNumbers[] = {"", "+", "-", " 1", "1 ", "\t1", "1\r", "1\n", "+ 1", "++1",
                                             "+-1", "-+1", "--1", "1-", "1+", "12a", "1,5", "x1"};

TEST(ParseNumbers, IntegersTakeEitherSign) {
  const std::pair<const char*, long long> cases[] = {
      {"0", 0}, {"7", 7}, {"-7", -7}, {"+7", 7}, {"-0", 0}, {"+0", 0}, {"+12345", 12345}, {"-12345", -12345}};
  for (const auto& [text, value] : cases) EXPECT_EQ(integer(text), value) << text;
}

TEST(ParseNumbers, IntegerTokensMustBeWhole) {
  for (const std::string_view text : kNotNumbers) EXPECT_EQ(integer(text), std::nullopt) << "'" << text << "'";
  // A real is not an integer here: whole_number, which falls back to
  // parse_real for "1.0", must see "1.5" refused rather than read as 1.
  for (const char* text : {"1.0", "1.5", "1e3", "1."}) EXPECT_EQ(integer(text), std::nullopt) << text;
}

// strtol with base 0 would read "010" as 8 and take "0x10": a node index
// written with leading zeros must keep its decimal value.
TEST(ParseNumbers, IntegersAreDecimalOnly) {
  EXPECT_EQ(integer("010"), 10);
  EXPECT_EQ(integer("-010"), -10);
  EXPECT_EQ(integer("00000000000000000000000000000007"), 7);  // more digits than any long long, still in range
  for (const char* text : {"0x10", "0X10", "0b1", "1_000"}) EXPECT_EQ(integer(text), std::nullopt) << text;
}

TEST(ParseNumbers, IntegersReachBothLimitsOfLongLong) {
  using limits = std::numeric_limits<long long>;
  EXPECT_EQ(integer("9223372036854775807"), limits::max());
  EXPECT_EQ(integer("+9223372036854775807"), limits::max());
  EXPECT_EQ(integer("-9223372036854775808"), limits::min());
  EXPECT_EQ(integer("2147483648"), 2147483648LL);  // past int: node tags may be
  EXPECT_EQ(integer("-2147483649"), -2147483649LL);
}

// One past either limit does not fit, and is refused rather than clamped or
// wrapped.
TEST(ParseNumbers, IntegersPastTheLimitsAreRefused) {
  for (const char* text : {"9223372036854775808", "+9223372036854775808", "-9223372036854775809",
                           "18446744073709551616", "99999999999999999999"})
    EXPECT_EQ(integer(text), std::nullopt) << text;
}

TEST(ParseNumbers, RealsTakeEitherSignAndEitherSideOfThePoint) {
  const std::pair<const char*, double> cases[] = {{"0", 0.0},    {"1.5", 1.5},   {"+1.5", 1.5}, {"-1.5", -1.5},
                                                  {"1.", 1.0},   {".5", 0.5},    {"-.5", -0.5}, {"+.5", 0.5},
                                                  {"00.5", 0.5}, {"42", 42.0}};
  for (const auto& [text, value] : cases) EXPECT_EQ(real(text), value) << text;
}

// The writers put "-0" for negative zero (test_number_text): it reads back
// with its sign.
TEST(ParseNumbers, NegativeZeroKeepsItsSign) {
  EXPECT_TRUE(std::signbit(real("-0").value_or(1)));
  EXPECT_TRUE(std::signbit(real("-0.0e5").value_or(1)));
  EXPECT_FALSE(std::signbit(real("+0").value_or(-1)));
}

TEST(ParseNumbers, RealsTakeExponents) {
  const std::pair<const char*, double> cases[] = {{"1e5", 1e5},     {"1E5", 1e5},     {"1e+05", 1e5},
                                                  {"+1e5", 1e5},    {"1e-05", 1e-5},  {"-2.5E-3", -2.5e-3},
                                                  {"1e0001", 10.0}, {"0e0", 0.0},     {".5e1", 5.0}};
  for (const auto& [text, value] : cases) EXPECT_EQ(real(text), value) << text;
}

TEST(ParseNumbers, RealTokensMustBeWhole) {
  for (const std::string_view text : kNotNumbers) EXPECT_EQ(real(text), std::nullopt) << "'" << text << "'";
  // An exponent marker needs digits after it; Fortran's D and C's f suffix are
  // not numbers.
  for (const char* text : {".", "+.", "-.", "e5", "1e", "1e+", "1e-", "1.2.3", "1d5", "1D5", "1.5f", "1.5e3x"})
    EXPECT_EQ(real(text), std::nullopt) << text;
}

// strtod would take hexadecimal floats; no mesh format writes them.
TEST(ParseNumbers, RealsAreDecimalOnly) {
  for (const char* text : {"0x1p3", "0x10", "0X1.8p1", "-0x1p-2"}) EXPECT_EQ(real(text), std::nullopt) << text;
}

// The nearest double, bit for bit, as the writers' shortest forms rely on.
TEST(ParseNumbers, RealsReadToTheNearestDouble) {
  using limits = std::numeric_limits<double>;
  EXPECT_EQ(bits(real("0.1").value_or(0)), bits(0.1));
  EXPECT_EQ(bits(real("0.30000000000000004").value_or(0)), bits(0.1 + 0.2));
  EXPECT_EQ(bits(real("0.3333333333333333").value_or(0)), bits(1.0 / 3));
  EXPECT_EQ(bits(real("1.7976931348623157e308").value_or(0)), bits(limits::max()));
  EXPECT_EQ(bits(real("-1.7976931348623157e+308").value_or(0)), bits(limits::lowest()));
  EXPECT_EQ(bits(real("2.2250738585072014e-308").value_or(0)), bits(limits::min()));
  EXPECT_EQ(bits(real("9007199254740993").value_or(0)), bits(9007199254740992.0));  // 2^53 + 1 rounds to even
}

// Subnormals fit, down to the smallest.
TEST(ParseNumbers, DenormalsAreRead) {
  using limits = std::numeric_limits<double>;
  EXPECT_EQ(bits(real("5e-324").value_or(0)), bits(limits::denorm_min()));
  EXPECT_EQ(bits(real("-4.9406564584124654e-324").value_or(0)), bits(-limits::denorm_min()));
  EXPECT_EQ(bits(real("2.225073858507201e-308").value_or(0)), bits(std::nextafter(limits::min(), 0.0)));
  EXPECT_EQ(bits(real("1e-320").value_or(0)), bits(1e-320));
}

// Past the largest double the value does not fit: refused, not read as inf
// (strtod would give inf). Values that round to zero are not pinned here:
// reading them as 0, as strtod-based tools do, would be as fair.
TEST(ParseNumbers, RealsOutOfRangeAreRefused) {
  for (const char* text : {"1e309", "-1e309", "1e999", "1.7976931348623159e308"})
    EXPECT_EQ(real(text), std::nullopt) << text;
}

// The caller decides about non-finite values (TextLines::real refuses them,
// a VTK field keeps its NaN), so parse_real reads them in any case.
TEST(ParseNumbers, NanAndInfAreRead) {
  for (const char* text : {"nan", "NaN", "NAN", "+nan", "-nan"}) {
    ASSERT_TRUE(real(text)) << text;
    EXPECT_TRUE(std::isnan(*real(text))) << text;
  }
  const double inf = std::numeric_limits<double>::infinity();
  for (const char* text : {"inf", "Inf", "+inf", "infinity", "INFINITY"}) EXPECT_EQ(real(text), inf) << text;
  EXPECT_EQ(real("-inf"), -inf);
  for (const char* text : {"na", "in", "infin", "nanx", "inf1", "-inf-"}) EXPECT_EQ(real(text), std::nullopt) << text;
}

}  // namespace
}  // namespace tetsmooth
