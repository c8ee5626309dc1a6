// The member tables (models/core/point_state_fields.hpp, kParticleArrays in
// mpm/particles/particles.hpp) and what derives from them: the member counter counts members,
// every line names its own member once, and every PointState member and every drawn particle
// array is a snapshot field (mpm/particles/snapshot_fields.hpp) whose values are the member's,
// component by component in the documented order. A member added without its line does not
// compile (the tables' static_asserts); these tests check the lines that are there, and that
// docs/mpm.md#snapshot-fields lists every field.
#include <boost/test/unit_test.hpp>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "models/core/point_state_fields.hpp"
#include "mpm/particles/snapshot_fields.hpp"

using namespace impact;
using namespace impact::mpm;

namespace {

struct FourMembers {
  Mat3 tensor;
  double number = 1.0;
  bool flag = false;
  std::vector<double> array;
};

// The byte offset of a member within a default-constructed object (distinct members, distinct
// offsets).
template <class Class, class T>
std::ptrdiff_t offset_of(T Class::*member) {
  static const Class object{};
  return reinterpret_cast<const char*>(&(object.*member)) - reinterpret_cast<const char*>(&object);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_particle_fields)

BOOST_AUTO_TEST_CASE(the_member_counter_counts_tensors_numbers_flags_and_arrays) {
  BOOST_TEST(aggregate_arity<FourMembers>() == 4u);
  BOOST_TEST(aggregate_arity<PointState>() == 15u);
}

BOOST_AUTO_TEST_CASE(every_state_line_names_its_own_member_once) {
  std::set<std::string> names;
  std::set<std::ptrdiff_t> offsets;
  std::size_t lines = 0;
  for_each_state_member([&](const auto& m) {
    ++lines;
    names.insert(m.name);
    offsets.insert(offset_of(m.member));
    BOOST_TEST(std::string(m.unit).size() > 0u, m.name);
  });
  BOOST_TEST(names.size() == lines);
  BOOST_TEST(offsets.size() == lines);
}

BOOST_AUTO_TEST_CASE(every_particle_line_names_its_own_array_once) {
  std::set<std::string> names;
  std::set<std::ptrdiff_t> offsets;
  std::size_t lines = 0, required_bytes = 0;
  for_each_particle_array([&](const auto& a) {
    ++lines;
    names.insert(a.name);
    offsets.insert(offset_of(a.member));
    if (!a.optional) required_bytes += sizeof(typename std::decay_t<decltype(a)>::Element);
  });
  BOOST_TEST(names.size() == lines);
  BOOST_TEST(offsets.size() == lines);
  // x, v (Vec3), mass, volume0, volume, wave_speed (double), L (Mat3), the state, and the
  // material, object and field indices (uint16): the storage `mpm check` reports.
  BOOST_TEST(Particles::bytes_per_particle() == 2 * 24 + 4 * 8 + 72 + sizeof(PointState) + 3 * 2);
  BOOST_TEST(required_bytes == Particles::bytes_per_particle());
}

BOOST_AUTO_TEST_CASE(every_state_member_is_a_snapshot_field_with_the_members_values) {
  Particles P;
  P.x = {Vec3(0.1, 0.2, 0.3)};
  P.v = {Vec3(1.0, -2.0, 3.5)};
  P.mass = {2.5e-3};
  P.volume0 = {1e-9};
  P.volume = {1.1e-9};
  P.L = {Mat3::Zero()};
  PointState s;
  s.stress << 1, 4, 6, 4, 2, 5, 6, 5, 3;
  s.F << 1.1, 0.2, 0.0, 0.1, 0.9, 0.3, 0.0, 0.0, 1.05;
  s.plastic_strain = 0.3;
  s.plastic_strain_rate = 2e4;
  s.temperature = 640.0;
  s.internal_energy = 1.5e5;
  s.damage = 0.4;
  s.porosity = 0.07;
  s.flow_internal = 3e8;
  s.melted = true;
  s.failed = true;
  s.failure_cause = FailureCause::tepla;
  s.instability = kBeckerFired;
  s.failed_in_tension = true;
  P.state = {s};
  P.wave_speed = {5000.0};
  P.material = {1};
  P.object = {2};
  P.field = {3};
  // One rank: no id array; the id is the particle's index.

  const auto value = [&](const std::string& name) {
    const SnapshotField* f = find_snapshot_field(name);
    BOOST_REQUIRE_MESSAGE(f, name + " is not a snapshot field");
    std::vector<double> out(static_cast<std::size_t>(f->components));
    f->values(P, 0, out.data());
    return out;
  };
  for_each_state_member([&](const auto& m) {
    const SnapshotField* f = find_snapshot_field(m.name);
    BOOST_REQUIRE_MESSAGE(f, std::string(m.name) + " is not a snapshot field");
    BOOST_TEST(f->unit == m.unit);
  });
  BOOST_TEST(value("stress") == std::vector<double>({1, 2, 3, 4, 5, 6}),
             boost::test_tools::per_element());
  BOOST_TEST(value("F") == std::vector<double>({1.1, 0.2, 0.0, 0.1, 0.9, 0.3, 0.0, 0.0, 1.05}),
             boost::test_tools::per_element());
  BOOST_TEST(value("R") == std::vector<double>({1, 0, 0, 0, 1, 0, 0, 0, 1}),
             boost::test_tools::per_element());
  BOOST_TEST(value("porosity")[0] == 0.07);
  BOOST_TEST(value("internal_energy")[0] == 1.5e5);
  BOOST_TEST(value("melted")[0] == 1.0);
  BOOST_TEST(value("failure_cause")[0] == double(FailureCause::tepla));
  BOOST_TEST(value("instability")[0] == double(kBeckerFired));
  BOOST_TEST(value("pressure")[0] == -2.0);
  BOOST_TEST(value("velocity") == std::vector<double>({1.0, -2.0, 3.5}),
             boost::test_tools::per_element());
  BOOST_TEST(value("mass")[0] == 2.5e-3);
  BOOST_TEST(value("object")[0] == 2.0);
  BOOST_TEST(value("id")[0] == 0.0);
  P.id = {41};
  BOOST_TEST(value("id")[0] == 41.0);
  // The step's own bookkeeping is not drawn.
  for (const char* internal : {"x", "v", "L", "wave_speed", "q", "fault", "removed", "volume0"})
    BOOST_TEST(find_snapshot_field(internal) == nullptr, internal);
}

// docs/mpm.md's table of snapshot fields names every field of the catalogue with its unit.
BOOST_AUTO_TEST_CASE(the_documented_snapshot_fields_are_the_catalogue) {
  std::ifstream in(std::string(IMPACT_SOURCE_DIR) + "/docs/mpm.md");
  const std::string doc{std::istreambuf_iterator<char>(in), {}};
  const auto start = doc.find("### Snapshot fields");
  BOOST_REQUIRE(start != std::string::npos);
  const std::string table = doc.substr(start, doc.find("\n###", start + 1) - start);
  for (const SnapshotField& f : snapshot_fields())
    BOOST_TEST(table.find("`" + f.name + "`") != std::string::npos, f.name + " is not documented");
}

BOOST_AUTO_TEST_SUITE_END()
