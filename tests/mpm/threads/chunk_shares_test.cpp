// Chunks dealt as contiguous shares and balanced by stealing (mpm/threads/chunk_shares.hpp): each
// chunk is taken exactly once, a thread takes its own share first and in order, and a thread whose
// share is done takes the other shares' last chunks. The stress update's energy sums rely on the
// first (mpm/step/stress_update.cpp) and its cache locality on the second.
#include <boost/test/unit_test.hpp>

#include <omp.h>

#include <algorithm>
#include <vector>

#include "mpm/threads/chunk_shares.hpp"

using impact::mpm::ChunkShares;

BOOST_AUTO_TEST_CASE(one_caller_takes_its_share_in_order_then_steals_the_others_backs) {
  // 10 chunks over 3 threads: shares [0, 3), [3, 6), [6, 10). Thread 1 alone asks for all of them.
  ChunkShares shares(10, 3);
  std::vector<std::ptrdiff_t> taken;
  for (std::ptrdiff_t c; (c = shares.next(1)) >= 0;) taken.push_back(c);
  // Its own share from the front, then the back of the share with the most left (thread 2's:
  // 4 chunks, then a tie of 3 and 3 goes to the first, thread 0's, and so on).
  const std::vector<std::ptrdiff_t> expected{3, 4, 5, 9, 2, 8, 1, 7, 0, 6};
  BOOST_TEST(taken == expected, boost::test_tools::per_element());
  BOOST_TEST(shares.next(0) == -1);
  BOOST_TEST(shares.next(2) == -1);
}

BOOST_AUTO_TEST_CASE(an_owner_keeps_the_front_of_its_share_while_another_steals_the_back) {
  ChunkShares shares(8, 2);                                         // [0, 4) and [4, 8)
  for (int k = 0; k < 4; ++k) BOOST_TEST(shares.next(1) == 4 + k);  // thread 1 done
  BOOST_TEST(shares.next(1) == 3);                                  // steals thread 0's last
  BOOST_TEST(shares.next(0) == 0);                                  // thread 0 keeps its front
  BOOST_TEST(shares.next(1) == 2);
  BOOST_TEST(shares.next(0) == 1);
  BOOST_TEST(shares.next(0) == -1);
  BOOST_TEST(shares.next(1) == -1);
}

BOOST_AUTO_TEST_CASE(every_chunk_is_taken_exactly_once_by_racing_threads) {
  // Uneven work (the first share's chunks are slow) so that the threads steal while the owners
  // still take; repeated to give the compare-and-swap races a chance.
  const int threads = 4;
  const std::ptrdiff_t count = 1001;
  for (int round = 0; round < 50; ++round) {
    ChunkShares shares(count, threads);
    std::vector<int> times(count, 0);
    std::vector<int> stolen(threads, 0);
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num();
      const std::ptrdiff_t lo = count * t / threads, hi = count * (t + 1) / threads;
      volatile double sink = 0.0;
      for (std::ptrdiff_t c; (c = shares.next(t)) >= 0;) {
#pragma omp atomic
        ++times[c];
        if (c < lo || c >= hi) ++stolen[t];
        for (int k = 0; k < (c < count / threads ? 2000 : 10); ++k) sink = sink + k;
      }
    }
    BOOST_TEST(std::all_of(times.begin(), times.end(), [](int n) { return n == 1; }),
               "round " << round);
  }
}
