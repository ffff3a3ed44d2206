// put_real and put_integer (mesh/io/number_text.hpp), the numbers of every
// ASCII writer: the shortest decimal that reads back to the same double,
// signs and exponents, the extremes of both types within their buffers,
// and text that the stream's flags and locale do not change.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <limits>
#include <locale>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mesh/io/number_text.hpp"

namespace tetsmooth {
namespace {

std::string real_text(double value) {
  std::ostringstream out;
  put_real(out, value);
  return out.str();
}

std::string integer_text(long long value) {
  std::ostringstream out;
  put_integer(out, value);
  return out.str();
}

std::uint64_t bits(double value) {
  std::uint64_t b = 0;
  std::memcpy(&b, &value, sizeof b);
  return b;
}

// The double that `text` reads back to, all of it taken; NaN when it is not
// one number.
double read_back(const std::string& text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::numeric_limits<double>::quiet_NaN();
  return value;
}

// `value` in scientific notation with the fewest significant digits that
// read back to it: the nearest decimal of n digits is tried for n = 1, 2, ...
// (when it does not read back, no decimal of n digits does).
std::string fewest_digits_scientific(double value) {
  char buf[64];
  for (int precision = 0;; ++precision) {
    const auto result = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::scientific, precision);
    std::string text(buf, result.ptr);
    if (read_back(text) == value) return text;
  }
}

TEST(NumberText, RealsTakeTheirShortestForm) {
  // 0.1 is not "0.10000000000000001", nor 1e22 twenty-two zeros.
  const std::pair<double, const char*> cases[] = {
      {0.0, "0"}, {1.0, "1"}, {-1.5, "-1.5"}, {0.1, "0.1"}, {-0.3, "-0.3"}, {100.0, "100"},
      {1e22, "1e+22"}, {1e-7, "1e-07"}, {-2.5e-5, "-2.5e-05"}, {123456789.0, "123456789"},
      {1.0 / 3, "0.3333333333333333"}};
  for (const auto& [value, text] : cases) EXPECT_EQ(real_text(value), text) << value;
}

// The sign of zero is kept, so that -0 reads back as -0.
TEST(NumberText, NegativeZeroKeepsItsSign) {
  EXPECT_EQ(real_text(-0.0), "-0");
  EXPECT_TRUE(std::signbit(read_back(real_text(-0.0))));
}

// The legacy VTK writer puts NaN on pass-through cells of a per-tet field.
TEST(NumberText, NonFiniteRealsAreNamed) {
  EXPECT_EQ(real_text(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(real_text(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(real_text(-std::numeric_limits<double>::infinity()), "-inf");
}

// The longest shortest forms fill their buffers without being cut: the
// header's 24-character example among them.
TEST(NumberText, ExtremesAreWrittenWhole) {
  using real = std::numeric_limits<double>;
  EXPECT_EQ(real_text(-real::min()), "-2.2250738585072014e-308");
  EXPECT_EQ(real_text(real::max()), "1.7976931348623157e+308");
  EXPECT_EQ(real_text(real::lowest()), "-1.7976931348623157e+308");
  EXPECT_EQ(real_text(real::denorm_min()), "5e-324");
  EXPECT_EQ(real_text(-std::nextafter(real::min(), 0.0)), "-2.225073858507201e-308");  // the largest subnormal

  using integer = std::numeric_limits<long long>;
  EXPECT_EQ(integer_text(integer::max()), "9223372036854775807");
  EXPECT_EQ(integer_text(integer::min()), "-9223372036854775808");
  EXPECT_EQ(integer_text(0), "0");
  EXPECT_EQ(integer_text(-7), "-7");
  EXPECT_EQ(integer_text(2147483648LL), "2147483648");  // past int: node tags may be
}

// Any finite double reads back bit for bit, in no more characters than the
// scientific form of its fewest digits (fixed notation may be as short).
TEST(NumberText, RealsReadBackExactlyInTheShortestText) {
  std::mt19937_64 random(20240611);
  std::vector<double> values = {0.1, 0.2, 0.7, 1e-5, 5e-324, 1.0 + std::numeric_limits<double>::epsilon()};
  for (int i = 0; i < 20000; ++i) {
    double v = 0;
    const std::uint64_t b = random();
    std::memcpy(&v, &b, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  for (int i = 0; i < 2000; ++i) values.push_back(std::uniform_real_distribution<double>(-10, 10)(random));
  for (const double v : values) {
    const std::string text = real_text(v);
    ASSERT_LE(text.size(), 24u) << text;
    ASSERT_EQ(bits(read_back(text)), bits(v)) << text;
    ASSERT_LE(text.size(), fewest_digits_scientific(v).size()) << text << " vs " << fewest_digits_scientific(v);
  }
}

// Writers may get a stream with any flags or locale; the file must not
// change with them (no "1,5", no hex, no "+", no 6 digits).
TEST(NumberText, StreamFlagsAndLocaleDoNotChangeTheText) {
  struct Comma : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
  };
  std::ostringstream out;
  out.imbue(std::locale(out.getloc(), new Comma));
  out << std::hex << std::showpos << std::showpoint << std::uppercase << std::fixed << std::setprecision(2)
      << std::setw(30) << std::setfill('*');
  put_real(out, 1234.5);
  out.put(' ');  // unformatted, as the width stays set for a formatted output to take
  put_real(out, 1.0 / 3);
  out.put(' ');
  put_real(out, 1e22);
  out.put(' ');
  put_integer(out, 1234567);
  out.put(' ');
  put_integer(out, -255);
  EXPECT_EQ(out.str(), "1234.5 0.3333333333333333 1e+22 1234567 -255");
}

// Each call appends its number to what the stream holds, and nothing else.
TEST(NumberText, NumbersAppendWithoutSeparators) {
  std::ostringstream out;
  out << "x=";
  put_real(out, 0.25);
  put_integer(out, 12);
  put_real(out, -3.0);
  EXPECT_EQ(out.str(), "x=0.2512-3");
}

}  // namespace
}  // namespace tetsmooth
