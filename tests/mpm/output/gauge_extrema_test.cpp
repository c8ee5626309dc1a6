// The gauges' extrema over the history rows (summary.json "gauges", docs/mpm.md#output), on
// readings given by hand: max, min, the signed peak of largest magnitude (a tie keeps the first
// row's) and its time, NaN readings skipped (a gauge whose particles have all left the grid),
// null before any finite reading, the units in the keys, and the checkpoint state restored into a
// fresh object continuing exactly as the uninterrupted one.
#include <boost/test/unit_test.hpp>
#include <limits>

#include "mpm/output/gauge_extrema.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_gauge_extrema)

BOOST_AUTO_TEST_CASE(max_min_peak_and_its_time) {
  GaugeExtrema e({"m/s", "Pa", "-"});
  e.sample({1.0, 5.0, kNaN}, 0.0);
  e.sample({-3.0, -5.0, kNaN}, 1e-6);  // -5: a tie with 5, the first stays the peak
  e.sample({2.0, 4.0, kNaN}, 2e-6);
  e.sample({kNaN, 1.0, kNaN}, 3e-6);  // gauge 0's particles gone: skipped
  const Json v = e.json(0), p = e.json(1), s = e.json(2);
  BOOST_TEST(v.at("max [m/s]").get<double>() == 2.0);
  BOOST_TEST(v.at("min [m/s]").get<double>() == -3.0);
  BOOST_TEST(v.at("peak [m/s]").get<double>() == -3.0);
  BOOST_TEST(v.at("peak_time [s]").get<double>() == 1e-6);
  BOOST_TEST(p.at("max [Pa]").get<double>() == 5.0);
  BOOST_TEST(p.at("min [Pa]").get<double>() == -5.0);
  BOOST_TEST(p.at("peak [Pa]").get<double>() == 5.0);
  BOOST_TEST(p.at("peak_time [s]").get<double>() == 0.0);
  // No finite reading: null, not a number that was never read.
  for (const char* key : {"max [-]", "min [-]", "peak [-]", "peak_time [s]"})
    BOOST_TEST(s.at(key).is_null(), key);
}

BOOST_AUTO_TEST_CASE(a_restored_state_continues_as_the_uninterrupted_one) {
  const std::vector<std::vector<double>> rows = {{0.5, kNaN}, {-0.25, 2.0}, {0.75, -3.0},
                                                 {-1.0, 1.0}, {1.0, 3.0},   {0.0, -4.0}};
  GaugeExtrema whole({"m/s", "-"}), first({"m/s", "-"});
  for (std::size_t i = 0; i < rows.size(); ++i) whole.sample(rows[i], 1e-6 * double(i));
  for (std::size_t i = 0; i < 3; ++i) first.sample(rows[i], 1e-6 * double(i));
  GaugeExtrema second({"m/s", "-"});
  second.restore(first.state());
  for (std::size_t i = 3; i < rows.size(); ++i) second.sample(rows[i], 1e-6 * double(i));
  for (std::size_t g = 0; g < 2; ++g) BOOST_TEST(second.json(g) == whole.json(g));
  BOOST_TEST(whole.json(0).at("peak [m/s]").get<double>() == -1.0);  // -1 before +1
  BOOST_TEST(whole.json(0).at("peak_time [s]").get<double>() == 3e-6);
  BOOST_TEST(whole.json(1).at("peak [-]").get<double>() == -4.0);
  BOOST_CHECK_THROW(second.restore({1.0, 2.0}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
