// docs/scenes.md against the scene reader: every key the reader asks for (recorded by
// mpm/input/scene_keys.hpp while it reads sample scenes with every block switched on) is listed
// in a key table of the docs with the same default and a consistent range, and the tables list
// no key the reader does not know. The conventions the docs' tables follow are stated at the
// top of docs/scenes.md.
#include "mpm/input/scene_keys.hpp"

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
#include "mpm/input/scene_reader.hpp"
#include "mpm/scene/scene.hpp"

using namespace impact;
using namespace impact::mpm;

using namespace impact::test;

namespace {

const std::string kSource = IMPACT_SOURCE_DIR;
const std::string kDocs = "docs/scenes.md";

/// One row of a key table of docs/scenes.md, for one key.
struct DocumentedKey {
  int line = 0;
  std::string default_text;  ///< the default column as written
  std::string type_text;     ///< the type (or values) column
  std::string meaning_text;  ///< the meaning column
};

/// Every key of every key table (header "key | ..."), as a dotted path: the table's section
/// heading (`grid`, `objects.<name>`, ...) followed by the row's key; `<face>` stands for each
/// of the six faces.
std::map<std::string, DocumentedKey> documented_keys(const std::string& file) {
  std::ifstream in(file);
  BOOST_REQUIRE_MESSAGE(in, "cannot read " << file);
  std::map<std::string, DocumentedKey> keys;
  std::string line, prefix;
  std::vector<std::string> header;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("#", 0) == 0) {
      const std::string title = trim(line.substr(line.find(' ')));
      prefix = title.rfind('`', 0) == 0 ? backticked(title).front() : std::string();
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
      for (std::size_t c = 0; c < header.size() && c < row.size(); ++c)
        for (const char* n : names)
          if (header[c] == n) return row[c];
      return std::string();
    };
    for (const std::string& key : backticked(row.front())) {
      std::vector<std::string> expanded{key};
      if (const auto at = key.find("<face>"); at != std::string::npos) {
        expanded.clear();
        for (const char* face : kFaceNames)
          expanded.push_back(key.substr(0, at) + face + key.substr(at + 6));
      }
      for (const std::string& k : expanded) {
        const std::string dotted = prefix.empty() ? k : prefix + "." + k;
        BOOST_CHECK_MESSAGE(keys.count(dotted) == 0,
                            kDocs << ":" << number << ": " << dotted << " is listed twice");
        keys[dotted] = {number, column({"default"}), column({"type", "values"}),
                        column({"meaning"})};
      }
    }
  }
  return keys;
}

/// Numbers compare by value (1.0 is 1, 1e4 is 10000), arrays element by element.
bool same_value(const std::string& docs, const std::string& reader) {
  const auto a = number_of(docs), b = number_of(reader);
  if (a && b) return *a == *b;
  if (docs.rfind('[', 0) == 0 && reader.rfind('[', 0) == 0) {
    std::stringstream x(docs.substr(1)), y(reader.substr(1));
    std::string p, q;
    while (std::getline(x, p, ',') && std::getline(y, q, ',')) {
      if (!same_value(trim(p.substr(0, p.find(']'))), trim(q.substr(0, q.find(']'))))) return false;
    }
    return !std::getline(x, p, ',') && !std::getline(y, q, ',');
  }
  return docs == reader;
}

/// The range a docs row states: "in (a, b]", "integers in a..b", ">= a" or "> a"; the type
/// column first, then the meaning.
std::optional<Interval> stated_range(const std::string& text) {
  static const std::regex interval(
      R"(in ([\(\[])\s*([-+0-9.einf]+),\s*([-+0-9.einf]+)\s*([\)\]]))");
  static const std::regex dots(R"(in ([-+0-9.e]+)\.\.([-+0-9.e]+))");
  static const std::regex bound(R"((>=?) ([-+0-9.e]+))");
  const double inf = INFINITY;
  std::smatch m;
  if (std::regex_search(text, m, interval))
    return Interval{std::strtod(m[2].str().c_str(), nullptr),
                    std::strtod(m[3].str().c_str(), nullptr), m[1] == "(", m[4] == ")"};
  if (std::regex_search(text, m, dots))
    return Interval{std::strtod(m[1].str().c_str(), nullptr),
                    std::strtod(m[2].str().c_str(), nullptr), false, false};
  if (std::regex_search(text, m, bound))
    return Interval{std::strtod(m[2].str().c_str(), nullptr), inf, m[1] == ">", true};
  return std::nullopt;
}

/// A union's parts are geometries: objects.<name>.geometry.parts.<name>.radius is documented as
/// objects.<name>.geometry.radius.
std::string documented_as(std::string key) {
  static const std::string part = "geometry.parts.<name>.";
  for (auto at = key.find(part); at != std::string::npos; at = key.find(part))
    key.replace(at, part.size(), "geometry.");
  return key;
}

bool is_map_entry(const std::string& key) {
  return key.size() >= 7 && key.compare(key.size() - 7, 7, ".<name>") == 0;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mpm_scene_keys)

BOOST_AUTO_TEST_CASE(the_reader_records_what_each_call_knows) {
  const InputKeyRecorder keys = scene_keys(kSource + "/data/materials/al6061_t6.json");
  const auto find = [&](const std::string& dotted) -> const KeyDescription* {
    for (const InputKey& k : keys.keys())
      if (dotted_key(k.path, kSceneKeyName) == dotted) return &k.description;
    return nullptr;
  };
  const KeyDescription* max_time = find("time.max_time");
  BOOST_REQUIRE(max_time != nullptr);
  BOOST_TEST(!max_time->default_value.has_value());  // required
  BOOST_TEST(max_time->range == "(0, inf)");
  BOOST_TEST(max_time->meaning == "end time [s]");
  const KeyDescription* multiplier = find("time.multiplier");
  BOOST_REQUIRE(multiplier != nullptr);
  BOOST_TEST(*multiplier->default_value == "0.5");
  BOOST_TEST(multiplier->range == "(0, 1.5]");
  const KeyDescription* ppc = find("objects.<name>.particles_per_cell");
  BOOST_REQUIRE(ppc != nullptr);
  BOOST_TEST(ppc->type == "[3 integers]");
  BOOST_TEST(ppc->range == "[1, 16]");
  BOOST_TEST(*ppc->default_value == "[2, 2, 2]");
  BOOST_TEST(*find("output.interval")->default_value == std::string(kComputedDefault));
  BOOST_TEST(find("objects.<name>.geometry.parts.<name>.type") != nullptr);  // a union's part
  BOOST_TEST(find("grid.wall_friction.z+") != nullptr);
  BOOST_TEST(find("extends") != nullptr);
}

BOOST_AUTO_TEST_CASE(recording_is_off_unless_asked_and_changes_no_result) {
  // The same scene read with and without a recorder: the same resolved scene, no key recorded
  // anywhere else (the recorder lives on the document's InputProblems).
  const Json doc =
      load_scene_document(kSource + "/data/scenes/verification/rigid_translation.json");
  InputKeyRecorder keys;
  const Scene with = read_scene(doc, "s.json", &keys);
  const Scene without = read_scene(doc, "s.json");
  BOOST_TEST(!keys.keys().empty());
  BOOST_TEST(with.time.multiplier == without.time.multiplier);
  BOOST_TEST(with.objects.size() == without.objects.size());
  BOOST_TEST(with.output.interval == without.output.interval);
}

BOOST_AUTO_TEST_CASE(docs_scenes_md_lists_every_key_with_the_readers_default_and_range) {
  const InputKeyRecorder recorder = scene_keys(kSource + "/data/materials/al6061_t6.json");
  const std::map<std::string, DocumentedKey> docs = documented_keys(kSource + "/" + kDocs);
  std::set<std::string> known;
  for (const InputKey& k : recorder.keys()) {
    const std::string key = documented_as(dotted_key(k.path, kSceneKeyName));
    if (is_map_entry(key)) continue;  // a named entry: its map's section heading documents it
    if (!known.insert(key).second) continue;  // a union part's key, checked as the geometry's
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
    const bool docs_required = doc.default_text.rfind("**required**", 0) == 0;
    if (!d.default_value) {
      BOOST_CHECK_MESSAGE(docs_required, where << "the docs' default is '" << doc.default_text
                                               << "', the reader requires the key");
    } else if (d.default_value->empty() || *d.default_value == kComputedDefault) {
      BOOST_CHECK_MESSAGE(!docs_required && !doc.default_text.empty(),
                          where << "the docs' default is '" << doc.default_text
                                << "', the reader's is "
                                << (d.default_value->empty() ? "no value (the key is optional)"
                                                             : "computed from the scene"));
    } else {
      const std::string stated = stated_default(doc.default_text);
      BOOST_CHECK_MESSAGE(same_value(stated, *d.default_value),
                          where << "the docs' default is '" << stated << "', the reader's '"
                                << *d.default_value << "'");
    }
    if (!d.range.empty() && d.range != "(-inf, inf)") {
      const Interval reader = reader_range(d.range);
      std::optional<Interval> stated = stated_range(doc.type_text);
      if (!stated) stated = stated_range(doc.meaning_text);
      if (!stated) {
        BOOST_ERROR(where << "the docs state no range, the reader's is " << d.range);
      } else {
        BOOST_CHECK_MESSAGE(*stated == reader, where << "the docs' range is " << text_of(*stated)
                                                     << ", the reader's " << d.range);
      }
    }
  }
  for (const auto& [key, doc] : docs) {
    BOOST_CHECK_MESSAGE(known.count(key) != 0, kDocs << ":" << doc.line << ": " << key
                                                     << " is listed, but the reader knows no "
                                                        "such key");
  }
}

BOOST_AUTO_TEST_SUITE_END()
