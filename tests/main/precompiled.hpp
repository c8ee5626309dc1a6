// The headers every test file parses, precompiled once for all of them (tests/CMakeLists.txt:
// impact_test_pch, reused by each test executable). Measured on the 2-core machine: a test file
// took 11-12 s to compile at -O3, 8.5-8.9 s with these precompiled. Only third-party and standard
// headers: a change to the project's own headers never rebuilds the precompiled header.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>
#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>
