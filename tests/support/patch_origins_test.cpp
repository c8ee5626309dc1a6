// support/patch_origins.hpp: a problem at a key a --set patch set is the patch's, not the file's.
// Expected messages are written out by hand from the rule (the last patch that set the key, a key
// above it or below it; a referenced material's value through the referring object's overrides).
#include "support/patch_origins.hpp"

#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

using namespace impact;

namespace {

std::string cli_name(std::size_t k) {
  return "--set patch " + std::to_string(k + 1);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(patch_origins)

BOOST_AUTO_TEST_CASE(the_last_patch_that_set_the_key_is_named) {
  const PatchOrigins o("s.json",
                       {Json::parse(R"({"time": {"multiplier": 2}, "grid": {"cells": [1, 2]}})"),
                        Json::parse(R"({"time": {"multiplier": 3}})")},
                       cli_name);
  BOOST_TEST(o.attribute("s.json: /time/multiplier: expected a number in (0, 1.5], got 3") ==
             "--set patch 2 (over s.json): /time/multiplier: expected a number in (0, 1.5], got 3");
  // An array replaces the whole value: its elements are the patch's.
  BOOST_TEST(o.attribute("s.json: /grid/cells/0: expected a positive integer") ==
             "--set patch 1 (over s.json): /grid/cells/0: expected a positive integer");
  // A key above one a patch set (a problem about the object holding it).
  BOOST_TEST(o.attribute("s.json: /time: expected an object") ==
             "--set patch 2 (over s.json): /time: expected an object");
  // Warnings too.
  BOOST_TEST(o.attribute("warning: s.json: /time/multiplier: 3 looks like ...") ==
             "warning: --set patch 2 (over s.json): /time/multiplier: 3 looks like ...");
}

BOOST_AUTO_TEST_CASE(problems_the_patches_did_not_touch_stay_the_files) {
  const PatchOrigins o("s.json", {Json::parse(R"({"time": {"multiplier": 2}})")}, cli_name);
  for (const std::string m :
       {"s.json: /time/max_time: expected a number in (0, inf)",  // a sibling of the patched key
        "s.json: /timer: unknown key (did you mean time?)",       // a key that only starts alike
        "s.json: /: expected a JSON object",                      // the top of the document
        "other.json: /time/multiplier: expected ...",             // another file
        "s.json: cannot open the file"}) {
    BOOST_TEST(o.attribute(m) == m);
  }
  // Without patches nothing changes.
  const PatchOrigins none("s.json", {}, cli_name);
  BOOST_TEST(none.attribute("s.json: /time/multiplier: x") == "s.json: /time/multiplier: x");
}

BOOST_AUTO_TEST_CASE(null_deletes_and_a_whole_document_patch) {
  const PatchOrigins o("m.json", {Json::parse(R"({"density": null})"), Json::parse("5")}, cli_name);
  // Patch 2 replaces the whole document: a problem at the top is its.
  BOOST_TEST(o.attribute("m.json: /: expected a JSON object with the material's properties") ==
             "--set patch 2 (over m.json): /: expected a JSON object with the material's "
             "properties");
  const PatchOrigins d("m.json", {Json::parse(R"({"density": null})")}, cli_name);
  BOOST_TEST(d.attribute("m.json: /density: missing required number in (0, 30000]") ==
             "--set patch 1 (over m.json): /density: missing required number in (0, 30000]");
}

BOOST_AUTO_TEST_CASE(a_referenced_material_value_set_through_overrides) {
  const PatchOrigins o("scene.json",
                       {Json::parse(R"({"materials": {"al": {"overrides": {"density": -1}}}})")},
                       [](std::size_t k) { return "patches[" + std::to_string(k) + "]"; });
  BOOST_TEST(o.attribute("scene.json: /materials/al/file: in material al.json: /density: "
                         "expected a number in (0, 30000], got -1") ==
             "patches[0] (over scene.json): /materials/al/file: in material al.json: /density: "
             "expected a number in (0, 30000], got -1");
  // Another value of the same material file is the file's own problem.
  const std::string own =
      "scene.json: /materials/al/file: in material al.json: /shear_modulus: expected ...";
  BOOST_TEST(o.attribute(own) == own);
}

// A patch that changes a block's "type" leaves the file's keys of the old type without a meaning
// (al6061_t6.json's Johnson-Cook A, B, C under a Swift "cowper_symonds" type): they were reported
// as the file's unknown keys.
BOOST_AUTO_TEST_CASE(keys_orphaned_by_a_patched_type_are_the_patchs) {
  const PatchOrigins o(
      "m.json",
      {Json::parse(R"({"constitutive_model": {"flow_stress": {"type": "cowper_symonds"}}})")},
      cli_name);
  BOOST_TEST(o.attribute("m.json: /constitutive_model/flow_stress/A: unknown key (did you mean "
                         "D?)") ==
             "--set patch 1 (over m.json): /constitutive_model/flow_stress/A: unknown key (did you "
             "mean D?); the patch's type does not take it: delete it in the patch (\"A\": null)");
  // Any other problem of the block, and an unknown key elsewhere, stay the file's.
  for (const std::string m : {"m.json: /constitutive_model/flow_stress/K: missing required number",
                              "m.json: /constitutive_model/damage/X: unknown key"}) {
    BOOST_TEST(o.attribute(m) == m);
  }
}

// The files of a scene's extends chain (mpm/input/scene_reader.hpp extends_origins): the name
// replaces the file, and a layer named "" (the scene file itself) keeps the message.
BOOST_AUTO_TEST_CASE(a_chain_of_files_names_the_file_that_set_the_key) {
  const std::vector<std::string> names = {"base.json (extended by s.json)", ""};
  const PatchOrigins o(
      "s.json",
      {Json::parse(R"({"grid": {"cell": [1, 1, 1]}, "time": {"max_time": 1}})"),
       Json::parse(R"({"time": {"max_time": -1}})")},
      [&](std::size_t k) { return names[k]; }, /*over_file=*/false);
  BOOST_TEST(o.attribute("s.json: /grid/cell: unknown key (did you mean cells?)") ==
             "base.json (extended by s.json): /grid/cell: unknown key (did you mean cells?)");
  BOOST_TEST(o.attribute("s.json: /time/max_time: expected a number in (0, inf), got -1") ==
             "s.json: /time/max_time: expected a number in (0, inf), got -1");
}

// A later layer that changes the type of a block whose keys an earlier one set: the keys the new
// type does not take are the later layer's doing, not the earlier's that set them (a scene that
// turns its base's box into a sphere was told its base's "lower" was an unknown key).
BOOST_AUTO_TEST_CASE(keys_a_later_layers_type_orphans_are_that_layers) {
  const std::vector<std::string> names = {"base.json (extended by s.json)", "", "--set patch 1"};
  const auto chain = [&](std::size_t k) { return names[k]; };
  const Json base = Json::parse(R"({"objects": {"b": {"geometry": {"type": "box",
      "lower": [0, 0, 0], "upper": [1, 1, 1]}}}})");
  const Json sphere = Json::parse(R"({"objects": {"b": {"geometry": {"type": "sphere"}}}})");
  const std::string lower =
      "s.json: /objects/b/geometry/lower: unknown key; known here: center, radius, type";
  const std::string hint =
      "; the patch's type does not take it: delete it in the patch "
      "(\"lower\": null)";
  // The scene file itself set the type: its name stays, with the hint.
  const PatchOrigins file({"s.json"}, {base, sphere}, chain, /*over_file=*/false);
  BOOST_TEST(file.attribute(lower) == lower + hint);
  // A third layer set it: that one is named.
  const PatchOrigins patch({"s.json"}, {base, Json::object(), sphere}, chain, false);
  BOOST_TEST(patch.attribute(lower) ==
             "--set patch 1: /objects/b/geometry/lower: unknown key; known here: center, radius, "
             "type" +
                 hint);
  // A layer that sets both the type and the key: its own unknown key, without the hint.
  const Json both = Json::parse(R"({"objects": {"b": {"geometry": {"type": "sphere",
      "lower": [0, 0, 0]}}}})");
  const PatchOrigins own({"s.json"}, {both, Json::object()}, chain, false);
  BOOST_TEST(own.attribute(lower) ==
             "base.json (extended by s.json): /objects/b/geometry/lower: unknown key; known "
             "here: center, radius, type");
}

// A derived scene often writes its base's type again: a typo of the base stays the base's, with
// no hint (the new rule above named the derived scene and told it to delete the key).
BOOST_AUTO_TEST_CASE(a_layer_that_repeats_the_type_orphans_nothing) {
  const std::vector<std::string> names = {"base.json (extended by s.json)", ""};
  const PatchOrigins o(
      {"s.json"},
      {Json::parse(R"({"objects": {"b": {"geometry": {"type": "box", "lowr": [0, 0, 0]}}}})"),
       Json::parse(R"({"objects": {"b": {"geometry": {"type": "box"}}}})")},
      [&](std::size_t k) { return names[k]; }, /*over_file=*/false);
  BOOST_TEST(o.attribute("s.json: /objects/b/geometry/lowr: unknown key (did you mean lower?)") ==
             "base.json (extended by s.json): /objects/b/geometry/lowr: unknown key (did you "
             "mean lower?)");
}

// Messages escape a key's / and ~ (RFC 6901: /objects/a~1b); the patches' keys are matched so.
BOOST_AUTO_TEST_CASE(a_key_with_a_slash_is_matched_as_the_messages_escape_it) {
  const PatchOrigins o("s.json", {Json::parse(R"({"objects": {"a/b~c": {"mu": 0.3}}})")}, cli_name);
  BOOST_TEST(o.attribute("s.json: /objects/a~1b~0c/mu: expected ...") ==
             "--set patch 1 (over s.json): /objects/a~1b~0c/mu: expected ...");
}

BOOST_AUTO_TEST_SUITE_END()
