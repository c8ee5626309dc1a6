// docs/models.md against the material reader: every key the reader asks for (recorded by
// models/material/material_keys.hpp while it reads sample materials with every block switched on
// and every catalogued model in its slot) is listed in a key table of the docs with the same
// default, a consistent range and, for a name, the same names; and the tables list no key the
// reader does not know. The conventions the docs' tables follow are stated in docs/models.md
// ("Rules for every key").
#include "models/material/material_keys.hpp"

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "helpers/key_tables.hpp"
#include "models/material/material.hpp"

using namespace impact;

using namespace impact::test;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;
const std::string kDocs = "docs/models.md";

/// One row of a key table of docs/models.md, for one key.
struct DocumentedKey {
  int line = 0;
  std::string default_text;  ///< the default column as written ("" when the table has none)
  std::string range_text;    ///< the range (or values) column
  std::string meaning_text;  ///< the meaning column
};

/// The key prefix a heading sets: "## `constitutive_model`" -> constitutive_model; "###
/// `flow_stress` (`type`: `zerilli_armstrong`)" ->
/// constitutive_model.flow_stress[zerilli_armstrong] (a model's keys in a catalogue slot); a
/// heading without a `key` -> its parent's prefix ("## Top level": none).
std::string heading_prefix(const std::string& title, int level, const std::string& parent) {
  const std::vector<std::string> words = backticked(title);
  if (words.empty()) return level <= 2 ? std::string() : parent;
  std::string prefix = level <= 2 || parent.empty() ? words.front() : parent + "." + words.front();
  static const std::regex model("\\(`type`: `([^`]+)`\\)");
  std::smatch m;
  if (std::regex_search(title, m, model)) {
    prefix += '[';
    prefix += m[1].str();
    prefix += ']';
  }
  return prefix;
}

/// Every key of every key table (header "key | ..."), as a dotted path: the table's section
/// prefix (heading_prefix) followed by the row's key; several keys in one cell share the row.
std::map<std::string, DocumentedKey> documented_keys(const std::string& file) {
  std::ifstream in(file);
  BOOST_REQUIRE_MESSAGE(in, "cannot read " << file);
  std::map<std::string, DocumentedKey> keys;
  std::string line, prefix, level2;
  std::vector<std::string> header;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("#", 0) == 0) {
      const auto level = static_cast<int>(line.find(' '));
      const std::string title = trim(line.substr(line.find(' ')));
      prefix = heading_prefix(title, level, level2);
      if (level <= 2) level2 = prefix;
      header.clear();
      continue;
    }
    if (line.rfind("|", 0) != 0) {
      header.clear();
      continue;
    }
    std::vector<std::string> row = cells(line);
    if (header.empty()) {
      header = row;
      continue;
    }
    if (header.front() != "key" || row.front().rfind("---", 0) == 0) continue;
    const auto column = [&](std::initializer_list<const char*> names) {
      for (const char* n : names)
        for (std::size_t c = 0; c < header.size() && c < row.size(); ++c)
          if (header[c] == n) return row[c];
      return std::string();
    };
    for (const std::string& key : backticked(row.front())) {
      const std::string dotted = prefix.empty() ? key : prefix + "." + key;
      BOOST_CHECK_MESSAGE(keys.count(dotted) == 0,
                          kDocs << ":" << number << ": " << dotted << " is listed twice");
      keys[dotted] = {number, column({"default"}), column({"range", "values"}),
                      column({"meaning"})};
    }
  }
  return keys;
}

bool states_required(const std::string& text) {
  return text.rfind("required", 0) == 0 || text.rfind("**required**", 0) == 0;
}

/// Numbers compare by value (1e-6 is 1e-06).
bool same_value(const std::string& docs, const std::string& reader) {
  const auto a = number_of(docs), b = number_of(reader);
  if (a && b) return *a == *b;
  return docs == reader;
}

/// The range a docs cell states: "(a, b]" (or "in (a, b]"), ">= a", "> a" or "any".
std::optional<Interval> stated_range(const std::string& text) {
  static const std::regex interval(R"(([\(\[])\s*([-+0-9.einf]+),\s*([-+0-9.einf]+)\s*([\)\]]))");
  static const std::regex bound(R"((>=?) ([-+0-9.e]+))");
  const double inf = INFINITY;
  std::smatch m;
  if (std::regex_search(text, m, interval))
    return Interval{std::strtod(m[2].str().c_str(), nullptr),
                    std::strtod(m[3].str().c_str(), nullptr), m[1] == "(", m[4] == ")"};
  if (std::regex_search(text, m, bound))
    return Interval{std::strtod(m[2].str().c_str(), nullptr), inf, m[1] == ">", true};
  if (trim(text).rfind("any", 0) == 0) return Interval{-inf, inf, true, true};
  return std::nullopt;
}

/// The names of a reader's "one of: a, b" type.
std::set<std::string> reader_names(const std::string& type) {
  std::set<std::string> names;
  std::stringstream list(type.substr(std::string("one of: ").size()));
  for (std::string name; std::getline(list, name, ',');) names.insert(trim(name));
  return names;
}

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

const KeyDescription* find(const InputKeyRecorder& keys, const std::string& dotted) {
  for (const InputKey& k : keys.keys())
    if (dotted_key(k.path, "") == dotted) return &k.description;
  return nullptr;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(material_keys_against_docs)

BOOST_AUTO_TEST_CASE(the_reader_records_every_catalogued_models_keys) {
  const InputKeyRecorder keys = material_keys();
  const KeyDescription* density = find(keys, "density");
  BOOST_REQUIRE(density != nullptr);
  BOOST_TEST(!density->default_value.has_value());  // required
  BOOST_TEST(density->range == "(0, 30000]");
  // The same key name in two laws: each with its own range, under its law's type.
  const KeyDescription* jc_n = find(keys, "constitutive_model.flow_stress[johnson_cook].n");
  const KeyDescription* scg_n =
      find(keys, "constitutive_model.flow_stress[steinberg_cochran_guinan].n");
  BOOST_REQUIRE(jc_n != nullptr);
  BOOST_REQUIRE(scg_n != nullptr);
  BOOST_TEST(jc_n->range == "(0, 1.5]");
  BOOST_TEST(scg_n->range == "[0, 1.5]");
  BOOST_TEST(find(keys, "constitutive_model.flow_stress.type") != nullptr);
  BOOST_TEST(find(keys, "constitutive_model.flow_stress.n") == nullptr);
  // Every model of every catalogue slot is read: one key of each (a model without keys, none).
  for (const char* key : {"flow_stress[zerilli_armstrong].C5", "flow_stress[cowper_symonds].q",
                          "flow_stress[preston_tonks_wallace].molar_mass",
                          "flow_stress[mechanical_threshold_stress].burgers",
                          "flow_stress[steinberg_cochran_guinan].U_k", "shear_modulus[varshni].T0",
                          "shear_modulus[nadal_le_poac].zeta", "damage[johnson_cook].D5",
                          "equation_of_state.mie_gruneisen.S_alpha", "melting.gamma0"})
    BOOST_TEST(find(keys, "constitutive_model." + std::string(key)) != nullptr, key);
  BOOST_TEST(
      *find(keys, "constitutive_model.damage[johnson_cook].cutoff_triaxiality")->default_value ==
      "");  // optional, no value
}

BOOST_AUTO_TEST_CASE(recording_is_off_unless_asked_and_changes_no_result) {
  const Json doc = load_json_file(kSource + "/data/materials/al6061_t6.json");
  InputKeyRecorder keys;
  const Material with = read_material(doc, "m.json", &keys);
  const Material without = read_material(doc, "m.json");
  BOOST_TEST(!keys.keys().empty());
  BOOST_TEST(to_json(with) == to_json(without));
}

BOOST_AUTO_TEST_CASE(docs_models_md_lists_every_key_with_the_readers_default_and_range) {
  const InputKeyRecorder recorder = material_keys();
  const std::map<std::string, DocumentedKey> docs = documented_keys(kSource + "/" + kDocs);
  std::set<std::string> known;
  for (const InputKey& k : recorder.keys()) {
    const std::string key = dotted_key(k.path, "");
    known.insert(key);
    const KeyDescription& d = k.description;
    const auto it = docs.find(key);
    if (it == docs.end()) {
      BOOST_ERROR(kDocs << " lists no key " << key << "; the reader reads it: " << d.type
                        << ", range " << (d.range.empty() ? "-" : d.range) << ", default "
                        << (!d.default_value           ? "required"
                            : d.default_value->empty() ? "none"
                                                       : *d.default_value)
                        << " (" << d.meaning << ")");
      continue;
    }
    const DocumentedKey& doc = it->second;
    const std::string where = kDocs + ":" + std::to_string(doc.line) + ": " + key + ": ";
    const bool docs_required = states_required(doc.default_text);
    if (!d.default_value) {
      BOOST_CHECK_MESSAGE(docs_required || doc.default_text.empty(),
                          where << "the docs' default is '" << doc.default_text
                                << "', the reader requires the key");
    } else if (d.default_value->empty()) {
      BOOST_CHECK_MESSAGE(!docs_required && !doc.default_text.empty(),
                          where << "the docs' default is '" << doc.default_text
                                << "', the reader's is no value (the key is optional)");
    } else {
      const std::string stated = stated_default(doc.default_text);
      BOOST_CHECK_MESSAGE(same_value(stated, *d.default_value),
                          where << "the docs' default is '" << stated << "', the reader's '"
                                << *d.default_value << "'");
    }
    if (!d.range.empty() && d.range != "(-inf, inf)") {
      const Interval reader = reader_range(d.range);
      std::optional<Interval> stated = stated_range(doc.range_text);
      if (!stated) stated = stated_range(doc.meaning_text);
      if (!stated) {
        BOOST_ERROR(where << "the docs state no range, the reader's is " << d.range);
      } else {
        BOOST_CHECK_MESSAGE(*stated == reader, where << "the docs' range is " << text_of(*stated)
                                                     << ", the reader's " << d.range);
      }
    }
    if (d.type.rfind("one of: ", 0) == 0) {
      const std::vector<std::string> listed = backticked(doc.range_text);
      const std::set<std::string> names(listed.begin(), listed.end());
      BOOST_CHECK_MESSAGE(names == reader_names(d.type),
                          where << "the docs list the names '" << joined(names)
                                << "', the reader knows '" << joined(reader_names(d.type)) << "'");
    }
  }
  for (const auto& [key, doc] : docs) {
    BOOST_CHECK_MESSAGE(known.count(key) != 0, kDocs << ":" << doc.line << ": " << key
                                                     << " is listed, but the reader knows no "
                                                        "such key");
  }
}

BOOST_AUTO_TEST_SUITE_END()
