#include <charconv>
#include <cmath>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "foldkit/io/number_format.hpp"

namespace {

using namespace foldkit::io;

TEST(NumberFormat, ShortestRoundTrip) {
  EXPECT_EQ(format_number(1.0), "1");
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(-0.0), "0");
  EXPECT_EQ(format_number(1e-300), "1e-300");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  for (int i = 0; i < 10000; ++i) {
    const double v = u(rng);
    const NumberList back = parse_numbers(format_number(v));
    ASSERT_TRUE(back.error.empty());
    EXPECT_EQ(back.values[0], v);
  }
}

TEST(NumberFormat, DegreesRoundTripRandom) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-M_PI, M_PI);
  std::uniform_int_distribution<int> deg(-180000000, 180000000);
  for (int i = 0; i < 10000; ++i) {
    // Any radians: within one unit in the last place; and a file's value is stable on re-write.
    const double r = u(rng);
    const std::string once = format_degrees(r);
    const double back = degrees_to_radians(parse_numbers(once).values[0]);
    EXPECT_LE(std::abs(back - r), 4.5e-16 * std::abs(r));
    EXPECT_EQ(format_degrees(back), once);
    // Degrees typed with six decimals come back as typed.
    const double typed = deg(rng) / 1e6;
    EXPECT_EQ(parse_numbers(format_degrees(degrees_to_radians(typed))).values[0], typed);
  }
}

// The search format_degrees once ran, kept as its oracle: every precision 1…17 on the product and
// its four neighbours either side, first that maps back wins.
std::optional<std::string> every_precision(double radians) {
  const double degrees = radians * (180.0 / M_PI);
  std::vector<double> candidates{degrees};
  for (double up = degrees, down = degrees; candidates.size() < 9;) {
    candidates.push_back(up = std::nextafter(up, HUGE_VAL));
    candidates.push_back(down = std::nextafter(down, -HUGE_VAL));
  }
  for (int digits = 1; digits <= 17; ++digits)
    for (double d : candidates) {
      char buf[40];
      auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d, std::chars_format::general, digits);
      if (ec != std::errc()) continue;
      double back = 0.0;
      std::from_chars(buf, end, back);
      if (degrees_to_radians(back) == radians) return format_number(back);
    }
  return std::nullopt;
}

std::string every_precision_degrees(double radians) {
  if (radians == 0.0) return "0";
  if (auto exact = every_precision(radians)) return *exact;
  if (auto exact = every_precision(degrees_to_radians(radians * (180.0 / M_PI)))) return *exact;
  return format_number(radians * (180.0 / M_PI));
}

TEST(NumberFormat, DegreesMatchEveryPrecisionSearch) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-M_PI, M_PI);
  std::uniform_int_distribution<int> deg(-180000, 180000);
  std::uniform_real_distribution<double> exponent(-300, 300);
  for (int i = 0; i < 20000; ++i) {
    for (double r : {u(rng), degrees_to_radians(deg(rng) / 1e3), degrees_to_radians(deg(rng)),
                     std::pow(10.0, exponent(rng)) * (i % 2 ? 1 : -1)})
      ASSERT_EQ(format_degrees(r), every_precision_degrees(r)) << std::hexfloat << r;
  }
  for (double typed : {1200.0, 90.0, 0.5, 1e-7, 123456789.0, 359.999999})
    EXPECT_EQ(format_degrees(degrees_to_radians(typed)), every_precision_degrees(degrees_to_radians(typed)));
}

TEST(NumberFormat, ParseRejectsNonFinite) {
  EXPECT_FALSE(parse_numbers("1 nan").error.empty());
  EXPECT_FALSE(parse_numbers("inf").error.empty());
  EXPECT_FALSE(parse_numbers("-infinity").error.empty());
  EXPECT_FALSE(parse_numbers("1e999").error.empty());
  EXPECT_FALSE(parse_numbers("1,2").error.empty());
  EXPECT_FALSE(parse_numbers("0x10").error.empty());
  EXPECT_EQ(parse_numbers(" +1.5\t-2e3\n").values, (std::vector<double>{1.5, -2000}));
  EXPECT_TRUE(parse_numbers("").values.empty());
}

TEST(NumberFormat, PlusSignIsFollowedByANumber) {
  EXPECT_EQ(parse_numbers("+5 +.5 +0.25e1").values, (std::vector<double>{5, 0.5, 2.5}));
  for (const char* bad : {"+-5", "++5", "+", "+inf", "+nan", "+ 5", "1 +-2"}) {
    const NumberList list = parse_numbers(bad);
    EXPECT_FALSE(list.error.empty()) << bad;
    EXPECT_NE(list.error.find("is not a number"), std::string::npos) << bad << ": " << list.error;
  }
}

TEST(NumberFormat, ParseInt) {
  EXPECT_EQ(parse_int(" 42 "), 42);
  EXPECT_EQ(parse_int("-7"), -7);
  EXPECT_FALSE(parse_int("4.0"));
  EXPECT_FALSE(parse_int("1e3"));
  EXPECT_FALSE(parse_int("2147483648"));
  EXPECT_FALSE(parse_int(""));
  EXPECT_FALSE(parse_int("12abc"));
}

TEST(NumberFormat, ParseIntAcceptsOnePlus) {
  EXPECT_EQ(parse_int("+5"), 5);
  EXPECT_EQ(parse_int(" +42\n"), 42);
  EXPECT_EQ(parse_int("+0"), 0);
  EXPECT_EQ(parse_int("+2147483647"), 2147483647);
  for (const char* bad : {"+-5", "++5", "+", "-+5", "+ 5", "+2147483648", "+x"}) EXPECT_FALSE(parse_int(bad)) << bad;
}

}  // namespace
