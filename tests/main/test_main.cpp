// The one main() of every Boost.Test executable (linked dynamically: BOOST_TEST_DYN_LINK). It lives
// here, compiled once, rather than in each test file through BOOST_TEST_MODULE, so that every test
// file can take Boost.Test's header from the tests' precompiled header (tests/CMakeLists.txt). The
// master test suite takes the executable's name, the CTest name, as BOOST_TEST_MODULE gave it.
#include <boost/test/unit_test.hpp>
#include <string>

namespace {

bool init_master_suite() {
  auto& master = boost::unit_test::framework::master_test_suite();
  if (master.argc > 0) {
    const std::string path = master.argv[0];
    master.p_name.value = path.substr(path.find_last_of('/') + 1);
  }
  return true;
}

}  // namespace

int main(int argc, char* argv[]) {
  return boost::unit_test::unit_test_main(&init_master_suite, argc, argv);
}
