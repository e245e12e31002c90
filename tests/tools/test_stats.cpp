// Mean, sample standard deviation and percent change, with numbers checked by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "stats.hpp"
#include "text_table.hpp"

using namespace swarm::tools;

TEST(Stats, MeanAndSampleStandardDeviation) {
  // Sum 40, mean 5; squared deviations 9+1+1+1+0+0+4+16 = 32; sample variance 32/7.
  const Summary s = summarize({2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_EQ(s.n, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.std, std::sqrt(32.0 / 7.0), 1e-12);  // 2.138...
  // Deviations -5.667, 28.333, -22.667: squares sum to 1348.667; / 2 = 674.333; sqrt = 25.968.
  const Summary m = summarize({368, 402, 351});
  EXPECT_NEAR(m.mean, 373.6667, 1e-4);
  EXPECT_NEAR(m.std, 25.9679, 1e-4);
}

TEST(Stats, OneValueHasNoSpreadAndNoValueHasNoMean) {
  const Summary one = summarize({42});
  EXPECT_EQ(one.n, 1u);
  EXPECT_DOUBLE_EQ(one.mean, 42);
  EXPECT_DOUBLE_EQ(one.std, 0);
  const Summary none = summarize({});
  EXPECT_EQ(none.n, 0u);
  EXPECT_TRUE(std::isnan(none.mean));
  EXPECT_EQ(format_mean_std(none, 1), "-");
}

TEST(Stats, PercentChangeAgainstAReference) {
  // The paper's Table 2: 173 vs 208 steps on open, 609 vs 711 on maze2.
  EXPECT_NEAR(*percent_change(173, 208), -16.8269, 1e-4);
  EXPECT_NEAR(*percent_change(609, 711), -14.3460, 1e-4);
  EXPECT_DOUBLE_EQ(*percent_change(150, 100), 50.0);
  EXPECT_FALSE(percent_change(1, 0).has_value());
  EXPECT_FALSE(percent_change(NAN, 10).has_value());
  // 36.36 % fewer rounds on average = the mean of the per-map changes (9/14, 17/31, 28/39).
  const auto mean = mean_of({percent_change(9, 14), percent_change(17, 31), percent_change(28, 39)});
  ASSERT_TRUE(mean.has_value());
  EXPECT_NEAR(*mean, -36.36, 0.01);
  EXPECT_NEAR(*mean_of({-10.0, std::nullopt, -20.0}), -15.0, 1e-12);
  EXPECT_FALSE(mean_of({std::nullopt}).has_value());
}

TEST(Stats, Formatting) {
  EXPECT_EQ(format_mean_std(summarize({368, 402, 351}), 1), "373.7 ± 26.0");
  EXPECT_EQ(format_mean_std(summarize({4, 4}), 0), "4 ± 0");
  EXPECT_EQ(format_percent_change(-16.8269), "-16.8 %");
  EXPECT_EQ(format_percent_change(2.0), "+2.0 %");
  EXPECT_EQ(format_percent_change(-0.01), "+0.0 %");  // never "-0.0 %"
  EXPECT_EQ(format_percent_change(std::nullopt), "-");
}

TEST(TextTable, AlignsColumnsCountingUtf8Characters) {
  TextTable t({"", "open", "maze1"});
  t.add_section("steps");
  t.add_row({"  group-frontier", "173.0 ± 1.0", "368.0 ± 12.5"});
  t.add_row({"  baseline", "208.0 ± 3.0"});
  EXPECT_EQ(t.render(),
            "                         open         maze1\n"
            "steps\n"
            "  group-frontier  173.0 ± 1.0  368.0 ± 12.5\n"
            "  baseline        208.0 ± 3.0\n");
  EXPECT_EQ(display_width("± ↔"), 3u);
}

TEST(Stats, StudentsTQuantileFromTheTableAndBeyondIt) {
  EXPECT_DOUBLE_EQ(t_quantile_975(1), 12.706);
  EXPECT_DOUBLE_EQ(t_quantile_975(4), 2.776);
  EXPECT_DOUBLE_EQ(t_quantile_975(30), 2.042);
  // Published values: 2.040 (31), 2.021 (40), 2.000 (60), 1.980 (120).
  EXPECT_NEAR(t_quantile_975(31), 2.040, 1e-3);
  EXPECT_NEAR(t_quantile_975(40), 2.021, 1e-3);
  EXPECT_NEAR(t_quantile_975(60), 2.000, 1e-3);
  EXPECT_NEAR(t_quantile_975(120), 1.980, 1e-3);
  EXPECT_TRUE(std::isnan(t_quantile_975(0)));
}

TEST(Stats, APairedDifferenceWithItsConfidenceInterval) {
  // Differences 2, 3, 1, 3, 1: mean 2, sample std 1, standard error 1 / sqrt 5 = 0.44721; t(4) =
  // 2.776, so 2 +- 1.24146 = [0.75854, 3.24146]; of the reference's mean 11: 18.18 % [6.896, 29.468].
  const PairedDifference d = paired_difference({12, 15, 11, 14, 13}, {10, 12, 10, 11, 12});
  EXPECT_EQ(d.n, 5u);
  EXPECT_DOUBLE_EQ(d.mean, 2.0);
  EXPECT_NEAR(d.low, 0.75854, 1e-4);
  EXPECT_NEAR(d.high, 3.24146, 1e-4);
  EXPECT_NEAR(d.mean_pct, 18.1818, 1e-4);
  EXPECT_NEAR(d.low_pct, 6.8958, 1e-3);
  EXPECT_NEAR(d.high_pct, 29.4678, 1e-3);
  EXPECT_TRUE(d.significant);
  EXPECT_EQ(format_paired_pct(d), "+18.2 % [+6.9, +29.5]");
  // Differences 1, -1, 2, -2: mean 0, the interval around it; not significant.
  const PairedDifference none = paired_difference({11, 9, 12, 8}, {10, 10, 10, 10});
  EXPECT_DOUBLE_EQ(none.mean, 0.0);
  EXPECT_LT(none.low, 0.0);
  EXPECT_GT(none.high, 0.0);
  EXPECT_FALSE(none.significant);
  EXPECT_EQ(format_paired_pct(none).substr(format_paired_pct(none).size() - 7), " (n.s.)");
  // One pair, or unpaired lists: no interval.
  EXPECT_EQ(format_paired_pct(paired_difference({1}, {2})), "-");
  EXPECT_EQ(format_paired_pct(paired_difference({1, 2}, {2})), "-");
}
