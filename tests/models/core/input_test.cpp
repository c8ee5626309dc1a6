// JSON reading: every problem names the file and the JSON key path, all problems are reported at
// once, unknown keys get a nearest-key suggestion.
#include "models/core/input.hpp"
#include "helpers/input_problems.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>

using namespace impact;
using impact::testing::problems_text;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// What parse_json_text says of `text` read as `what`: its InputError, or "no error: " and the JSON.
std::string parse_message(const std::string& text, const std::string& what) {
  try {
    const Json parsed = parse_json_text(text, what);
    return "no error: " + parsed.dump();
  } catch (const InputError& e) {
    return std::string(e.what());
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(core_input)

BOOST_AUTO_TEST_CASE(a_valid_object_reads_without_problems) {
  const Json j = Json::parse(R"({"a": 2.5, "flag": true, "kind": "x", "sub": {"b": 1}})");
  InputProblems problems("f.json");
  JsonReader r(j, "", problems);
  BOOST_TEST(r.number("a", Range::positive(), "") == 2.5);
  BOOST_TEST(r.boolean_or("flag", false, "") == true);
  BOOST_TEST(r.choice("kind", {"x", "y"}, "") == "x");
  JsonReader sub = r.child("sub", "");
  BOOST_TEST(sub.number_or("b", 0.0, Range::any(), "") == 1.0);
  BOOST_TEST(sub.number_or("c", 7.0, Range::any(), "") == 7.0);
  sub.reject_unknown_keys();
  r.reject_unknown_keys();
  BOOST_TEST(problems.empty());
}

BOOST_AUTO_TEST_CASE(every_problem_is_reported_with_file_and_key_path) {
  const Json j = Json::parse(R"({"a": -1, "b": "text", "sub": {"kind": "z", "extra": 1}})");
  InputProblems problems("model.json");
  JsonReader r(j, "", problems);
  r.number("a", Range::positive(), "a positive thing [Pa]");
  r.number("b", Range::any(), "");
  r.number("missing", Range::closed(0.0, 1.0), "");
  JsonReader sub = r.child("sub", "");
  sub.choice("kind", {"x", "y"}, "the kind");
  sub.reject_unknown_keys();
  r.reject_unknown_keys();
  const std::string text = problems_text(problems);
  BOOST_TEST(contains(
      text, "model.json: /a: expected a number in (0, inf), got -1 (a positive thing [Pa])"));
  BOOST_TEST(
      contains(text, "model.json: /b: expected a number in (-inf, inf), got the string \"text\""));
  BOOST_TEST(contains(text, "model.json: /missing: missing required number in [0, 1]"));
  BOOST_TEST(contains(text, "model.json: /sub/kind: unknown name \"z\"; known: x, y"));
  BOOST_TEST(contains(text, "model.json: /sub/extra: unknown key"));
}

// A value just outside its range is shown to every digit that tells it from the bound (the trial:
// growth 2.0000001 refused as "got 2", beside "[1.05, 2]").
BOOST_AUTO_TEST_CASE(a_value_just_outside_its_range_is_shown_as_written) {
  const Json j = Json::parse(R"({"growth": 2.0000001, "small": 1e-7})");
  InputProblems problems("s.json");
  JsonReader r(j, "", problems);
  r.number("growth", Range::closed(1.05, 2.0), "");
  r.number("small", Range::closed(1.0, 2.0), "");
  const std::string text = problems_text(problems);
  BOOST_TEST_MESSAGE(text);
  BOOST_TEST(contains(text, "s.json: /growth: expected a number in [1.05, 2], got 2.0000001"));
  BOOST_TEST(contains(text, "s.json: /small: expected a number in [1, 2], got 1e-07"));
}

BOOST_AUTO_TEST_CASE(unknown_key_suggests_the_nearest_known_key) {
  const Json j = Json::parse(R"({"densty": 2700})");
  InputProblems problems("m.json");
  JsonReader r(j, "", problems);
  r.number_or("density", 1.0, Range::positive(), "");
  r.reject_unknown_keys();
  BOOST_TEST(contains(problems_text(problems), "/densty: unknown key (did you mean density?)"));
}

// With no near name, the few keys a place reads are listed ("x_minus" is far from "x-").
BOOST_AUTO_TEST_CASE(an_unknown_key_with_no_near_name_lists_the_known_ones) {
  const Json j = Json::parse(R"({"x_minus": 0.3, "x-": 0.1})");
  InputProblems problems("s.json");
  JsonReader r(j, "/grid/wall_friction", problems);
  for (const char* face : {"x-", "x+", "y-"}) r.number_or(face, 0.0, Range::closed(0.0, 10.0), "");
  r.reject_unknown_keys();
  BOOST_TEST(problems_text(problems) ==
             "s.json: /grid/wall_friction/x_minus: unknown key; known here: x+, x-, y-");
}

BOOST_AUTO_TEST_CASE(a_line_based_file_names_the_line_instead_of_a_key_path) {
  InputProblems problems("curve.csv");
  problems.add_at_line(7, "column 2 (true_stress [Pa]): empty cell");
  problems.add_at_line(0, "no data rows (empty curve)");  // the file as a whole
  problems.add("/x", "at a key path, as before");
  BOOST_TEST(problems.line_location(3) == "curve.csv:3");
  BOOST_TEST(problems.line_location(0) == "curve.csv");
  const std::vector<std::string> expected{"curve.csv:7: column 2 (true_stress [Pa]): empty cell",
                                          "curve.csv: no data rows (empty curve)",
                                          "curve.csv: /x: at a key path, as before"};
  BOOST_CHECK_EXCEPTION(problems.throw_if_any(), InputError,
                        [&](const InputError& e) { return e.problems() == expected; });
}

BOOST_AUTO_TEST_CASE(nearest_name_ignores_names_that_are_too_different) {
  BOOST_TEST(!nearest_name("temperature", {"A", "B", "n"}).has_value());
  BOOST_TEST(nearest_name("johnson_cok", {"johnson_cook", "none"}).value() == "johnson_cook");
}

BOOST_AUTO_TEST_CASE(syntax_errors_and_missing_files_name_the_file) {
  BOOST_CHECK_EXCEPTION(load_json_file("/nonexistent/x.json"), InputError, [](const InputError& e) {
    return contains(e.what(), "/nonexistent/x.json: cannot open the file");
  });
}

// A key written twice in one object: nlohmann::json keeps the last without a word (a scene with
// two "time" blocks ran with the second). An InputError naming the key path; the same key in two
// objects, or in objects of an array, is fine.
BOOST_AUTO_TEST_CASE(a_key_written_twice_in_one_object_is_an_input_error) {
  const auto message = [](const std::string& text) { return parse_message(text, "scene.json"); };
  const std::string twice =
      " appears twice in its object (JSON would keep only the last); "
      "write it once";
  BOOST_TEST(message(R"({"time": {"a": 1}, "time": {"a": 2}})") ==
             "scene.json: /time: the key \"time\"" + twice);
  BOOST_TEST(message(R"({"a": [{"b": 1}, {"c": 1, "c": 2}]})") ==
             "scene.json: /a/1/c: the key \"c\"" + twice);
  BOOST_TEST(message(R"({"a": {"b": 1}, "c": {"b": 1}, "d": [{"b": 1}, {"b": 2}]})") ==
             "no error: {\"a\":{\"b\":1},\"c\":{\"b\":1},\"d\":[{\"b\":1},{\"b\":2}]}");
}

// RFC 6901, section 3: a key holding '/' or '~' is one reference token, escaped "~1" and "~0"
// (the '~' first, so "~1" in a key stays two characters of the key).
BOOST_AUTO_TEST_CASE(a_key_with_a_slash_or_tilde_is_one_token_of_its_key_path) {
  BOOST_TEST(pointer_token("block") == "block");
  BOOST_TEST(pointer_token("a/b") == "a~1b");
  BOOST_TEST(pointer_token("~1") == "~01");
  BOOST_TEST(pointer_token("/~/") == "~1~0~1");
  BOOST_TEST(pointer_token("") == "");
  // Through a reader: the unknown key inside the object named "top/left".
  const Json j = Json::parse(R"({"objects": {"top/left": {"velocty": 1}}})");
  InputProblems problems("s.json");
  JsonReader root(j, "", problems);
  JsonReader objects = root.child("objects", "");
  JsonReader object = objects.child("top/left", "");
  object.reject_unknown_keys();
  BOOST_TEST(contains(problems_text(problems), "s.json: /objects/top~1left/velocty: unknown key"));
  // And the parse's own key paths (a key written twice).
  BOOST_TEST(parse_message(R"({"a/b": {"~": 1, "~": 2}})", "s.json") ==
             "s.json: /a~1b/~0: the key \"~\" appears twice in its object (JSON would keep only "
             "the last); write it once");
}

// A number no double holds (1e999, -1e400, a 400-digit integer) is valid JSON that nlohmann::json
// refuses with out_of_range: before, it escaped every --set (SIGABRT) and the Python patches
// (RuntimeError). It is an InputError naming what was parsed and the key path of the number.
BOOST_AUTO_TEST_CASE(a_number_beyond_the_double_range_names_its_key_path) {
  const auto message = [](const std::string& text) { return parse_message(text, "--set patch 2"); };
  const std::string range = "is beyond the range of a double (magnitude at most 1.8e308)";
  BOOST_TEST(message(R"({"density": 1e999})") ==
             "--set patch 2: /density: the number 1e999 " + range);
  BOOST_TEST(message(R"({"a": {"b": [1, {"c": 2}, -1e400]}, "d": 1})") ==
             "--set patch 2: /a/b/2: the number -1e400 " + range);
  BOOST_TEST(message("1e999") == "--set patch 2: /: the number 1e999 " + range);
  BOOST_TEST(message(R"({"n": 1)" + std::string(400, '0') + "}") ==
             "--set patch 2: /n: the number 1000000000000000... (401 characters) " + range);
  // Still numbers: the largest double, an integer beyond int64 but within the double range, the
  // smallest subnormal, zero however written.
  BOOST_TEST(parse_json_text(R"({"a": 1.7976931348623157e308})", "x")["a"].get<double>() ==
             1.7976931348623157e308);
  BOOST_TEST(parse_json_text(R"({"a": 1)" + std::string(30, '0') + "}", "x")["a"].get<double>() ==
             1e30);
  BOOST_TEST(parse_json_text(R"({"a": 5e-324})", "x")["a"].get<double>() > 0.0);
  BOOST_TEST(parse_json_text(R"({"a": [0e-400, -0.0E-5, 1e-5]})", "x")["a"][0].get<double>() ==
             0.0);
  // Below the range: 1e-400 read as 0 without a word, so that a density of 1e-400 was reported
  // "got 0". Now an input error, like 1e999.
  const std::string below =
      "is below the range of a double (magnitude at least 4.9e-324) and would read as 0; write 0 "
      "if 0 is meant";
  BOOST_TEST(message(R"({"b": 1e-5, "a": [1, -1.5e-400]})") ==
             "--set patch 2: /a/1: the number -1.5e-400 " + below);
  BOOST_TEST(message(R"({"density": 1E-400})") ==
             "--set patch 2: /density: the number 1E-400 " + below);
  BOOST_TEST(contains(message(R"({"a": 1,})"), "--set patch 2: JSON syntax error at byte 9"));
}

BOOST_AUTO_TEST_CASE(a_file_with_an_out_of_range_number_names_file_and_key) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("input_test_range_" + std::to_string(::getpid()) + ".json");
  {
    std::ofstream out(file);
    out << R"({"density": 2700, "constitutive_model": {"flow_stress": {"A": 1e999}}})";
  }
  BOOST_CHECK_EXCEPTION(load_json_file(file.string()), InputError, [&](const InputError& e) {
    return std::string(e.what()) == file.string() +
                                        ": /constitutive_model/flow_stress/A: the number 1e999 "
                                        "is beyond the range of a double (magnitude at most "
                                        "1.8e308)";
  });
  std::filesystem::remove(file);
}

// A FIFO given as a material file used to block the run forever (the open waits for a writer);
// a directory opened, then failed to read. Both are refused before any read.
BOOST_AUTO_TEST_CASE(special_files_are_refused_without_blocking) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("input_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string fifo = (dir / "material.json").string();
  BOOST_REQUIRE_EQUAL(::mkfifo(fifo.c_str(), 0600), 0);
  const auto refused = [](const std::string& file, const std::string& kind) {
    return [file, kind](const InputError& e) {
      return std::string(e.what()) == file + ": " + kind + "; expected a JSON file";
    };
  };
  BOOST_CHECK_EXCEPTION(load_json_file(fifo), InputError,
                        refused(fifo, "is not a regular file (a FIFO, socket or device)"));
  // A directory says so (it was "not a regular file (a directory, FIFO, socket or device)").
  BOOST_CHECK_EXCEPTION(load_json_file(dir.string()), InputError,
                        refused(dir.string(), "is a directory"));
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(range_descriptions_show_open_and_closed_ends) {
  BOOST_TEST(Range::open_closed(0.0, 1.0).describe() == "(0, 1]");
  BOOST_TEST(Range::closed(0.0, 1.0).contains(1.0));
  BOOST_TEST(!Range::open(0.0, 1.0).contains(1.0));
  BOOST_TEST(!Range::any().contains(std::numeric_limits<double>::quiet_NaN()));
}

BOOST_AUTO_TEST_SUITE_END()
