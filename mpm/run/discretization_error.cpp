#include "mpm/run/discretization_error.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace impact::mpm {

namespace {

namespace fs = std::filesystem;

// A malformed table: the reason, naming the key path.
struct Unreadable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const Json& member(const Json& node, const std::string& key, const std::string& path) {
  if (!node.is_object()) throw Unreadable(path + ": expected an object");
  const auto it = node.find(key);
  if (it == node.end()) throw Unreadable(path + "/" + key + ": missing");
  return *it;
}

std::string string_at(const Json& node, const std::string& key, const std::string& path) {
  const Json& v = member(node, key, path);
  if (!v.is_string()) throw Unreadable(path + "/" + key + ": expected a string, got " + v.dump());
  return v.get<std::string>();
}

// A number or null (the ladder could not extrapolate).
Json number_or_null(const Json& node, const std::string& key, const std::string& path) {
  const Json& v = member(node, key, path);
  if (!v.is_number() && !v.is_null())
    throw Unreadable(path + "/" + key + ": expected a number or null, got " + v.dump());
  return v;
}

const Json& array_at(const Json& node, const std::string& key, const std::string& path) {
  const Json& v = member(node, key, path);
  if (!v.is_array()) throw Unreadable(path + "/" + key + ": expected an array");
  return v;
}

// The relative error of `value` against the extrapolated value, only where the ladder says the
// extrapolation may be quoted (in the asymptotic range, a plausible order): elsewhere a signed
// error against one extrapolated number misleads (issue 52: -180.9 % off an "extrapolated"
// +22.8 m/s while every level was negative), and the entry carries the ladder's range instead.
// null when there is no extrapolated value or it is 0.
void set_error(Json& out, double value) {
  out["value"] = value;
  const Json& extrapolated = out["extrapolated"];
  const double x = extrapolated.is_number() ? extrapolated.get<double>() : 0.0;
  const bool quotable = out["quotable"].get<bool>();
  out["error [-]"] = quotable && x != 0.0 ? Json((value - x) / std::abs(x)) : Json(nullptr);
}

// A table made by another code or other material data: the run repeats the level's scene (same
// fingerprint) but not its value, so the ladder's numbers no longer describe this run (issue 52:
// a stale table applied silently). Particle state is bit for bit the same on any thread count,
// particle sums differ by round-off (docs/mpm.md); other ranks, compilers or machines move an
// observable by round-off, which an impact may amplify, so the tolerance is the larger of 1e-3
// relative and 1 % of the smallest change the ladder saw between this level and a neighbour (a
// value near 0 is not stale for round-off). A stale entry says so, is not quotable, keeps the
// table's range under the stale verdict and gives the ladder's value beside this run's. Tables
// without "values" are not checked.
constexpr double kStaleRelative = 1e-3;     // of the value [-]
constexpr double kStaleOfLevelStep = 1e-2;  // of the change to a neighbouring level [-]

void mark_if_stale(Json& out, const Json& o, const std::string& path, std::size_t level_index,
                   std::size_t level_count) {
  const auto values = o.find("values");
  if (values == o.end()) return;
  if (!values->is_array() || values->size() != level_count) {
    throw Unreadable(path + "/values: expected one entry per level (" +
                     std::to_string(level_count) + ")");
  }
  const Json& table_value = (*values)[level_index];
  if (!table_value.is_number()) return;  // that level's run gave no value: nothing to compare
  const double ladder = table_value.get<double>();
  const double value = out["value"].get<double>();
  double tolerance = kStaleRelative * std::max(std::abs(ladder), std::abs(value));
  std::optional<double> step;
  for (const std::size_t j : {level_index - 1, level_index + 1}) {
    if (j >= level_count || !(*values)[j].is_number()) continue;  // (level_index - 1 wraps)
    const double d = std::abs((*values)[j].get<double>() - ladder);
    if (d > 0.0 && (!step || d < *step)) step = d;
  }
  if (step) tolerance = std::max(tolerance, kStaleOfLevelStep * *step);
  if (!(std::abs(value - ladder) > tolerance)) return;
  std::ostringstream why;
  why.precision(6);
  why << "stale: this run gives " << value << ", the ladder's run of this level gave " << ladder
      << " (the code or the material data changed since the ladder was run): re-run the ladder";
  out["status"] = why.str();
  out["verdict"] = "stale table: re-run the ladder";
  out["quotable"] = false;
  out["error [-]"] = nullptr;
  out["ladder_value"] = ladder;
}

// The range the levels and the plausible orders bound (ladder.py: {"low", "high", "unit",
// "basis"}), copied as given when it is one.
std::optional<Json> range_of(const Json& o, const std::string& path) {
  const auto it = o.find("range");
  if (it == o.end() || it->is_null()) return std::nullopt;
  if (!it->is_object()) throw Unreadable(path + "/range: expected an object or null");
  for (const char* key : {"low", "high"}) {
    const auto v = it->find(key);
    if (v == it->end() || !v->is_number())
      throw Unreadable(path + "/range/" + key + ": expected a number");
  }
  return *it;
}

// The observable's entry: the table's numbers with this run's value and its relative error. A
// pointer that is not one gives a status instead; nullopt when it names no number here. A null
// path marks an observable the summary does not hold (a Taylor rod's Lf and Dm, measured from
// snapshots by campaigns/study/ladder.py): its value is the ladder's own for the matching level
// (`level_index` into "values"), which this run repeats bit for bit (same fingerprint).
std::optional<Json> observable(const Json& o, const std::string& path, const Json& summary,
                               std::size_t level_index, std::size_t level_count) {
  const Json& named = member(o, "path", path);
  Json out = {{"path", named.is_null() ? Json(nullptr) : Json(string_at(o, "path", path))},
              {"extrapolated", number_or_null(o, "extrapolated", path)},
              {"gci_fine [-]", number_or_null(o, "gci_fine [-]", path)},
              {"order", number_or_null(o, "order", path)},
              {"status", string_at(o, "status", path)}};
  // Optional (tables before it lack it): the conservative GCI of Oberkampf & Roy (2010).
  if (o.contains("gci_conservative [-]"))
    out["gci_conservative [-]"] = number_or_null(o, "gci_conservative [-]", path);
  // Whether one extrapolated value may be quoted: the table's word (tables before issue 52 lack
  // it, and are then never quotable), and the range to quote otherwise.
  const auto quotable = o.find("quotable");
  if (quotable != o.end() && !quotable->is_boolean())
    throw Unreadable(path + "/quotable: expected true or false, got " + quotable->dump());
  out["quotable"] = quotable != o.end() && quotable->get<bool>();
  if (auto range = range_of(o, path)) out["range"] = std::move(*range);
  // The short verdict (tables before issue 52 lack it: then the status says it at length).
  if (o.contains("verdict")) out["verdict"] = string_at(o, "verdict", path);
  if (named.is_null()) {
    const Json& values = array_at(o, "values", path);
    if (values.size() != level_count) {
      throw Unreadable(path + "/values: expected one entry per level (" +
                       std::to_string(level_count) + "), got " + std::to_string(values.size()));
    }
    const Json& v = values[level_index];
    if (!v.is_number() && !v.is_null()) {
      throw Unreadable(path + "/values/" + std::to_string(level_index) +
                       ": expected a number or null, got " + v.dump());
    }
    if (v.is_null()) return std::nullopt;  // that level's run gave no value
    set_error(out, values[level_index].get<double>());
    out["value_source"] = "the ladder's run of this level (campaigns/study/ladder.py)";
    return out;
  }
  Json::json_pointer pointer;
  try {
    pointer = Json::json_pointer(out["path"].get<std::string>());
  } catch (const Json::exception&) {  // not a JSON pointer (RFC 6901)
    out["status"] = "path not found in this run's summary";
    return out;
  }
  const Json* found = nullptr;
  try {
    if (summary.contains(pointer)) found = &summary.at(pointer);
  } catch (const Json::exception&) {  // e.g. "/a/b" where /a is an array: not found
  }
  if (found == nullptr || !found->is_number()) return std::nullopt;
  set_error(out, found->get<double>());
  mark_if_stale(out, o, path, level_index, level_count);
  return out;
}

Json from_table(const std::string& table, const Json& doc, const std::string& fingerprint,
                const Json& summary) {
  if (!doc.is_object()) throw Unreadable("/: expected an object");
  const Json& levels = array_at(doc, "levels", "");
  const Json* match = nullptr;
  std::size_t match_index = 0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const std::string path = "/levels/" + std::to_string(i);
    const std::string f = string_at(levels[i], "fingerprint", path);
    const Json& level = member(levels[i], "level", path);
    if (!level.is_number())
      throw Unreadable(path + "/level: expected a number, got " + level.dump());
    for (std::size_t j = 0; j < i; ++j) {
      if (levels[j]["fingerprint"] == f) {
        throw Unreadable(path + "/fingerprint: the same as /levels/" + std::to_string(j) +
                         "/fingerprint (two levels cannot be one scene)");
      }
    }
    if (f == fingerprint && match == nullptr) {
      match = &levels[i];
      match_index = i;
    }
  }
  const Json& observables = array_at(doc, "observables", "");
  const std::string commit = string_at(doc, "commit", "");
  if (match == nullptr) {
    return {
        {"table", table},
        {"status", "no level of the ladder matches this scene (fingerprint " + fingerprint + ")"}};
  }
  Json entries = Json::object();
  for (std::size_t i = 0; i < observables.size(); ++i) {
    const std::string path = "/observables/" + std::to_string(i);
    const std::string name = string_at(observables[i], "name", path);
    if (auto entry = observable(observables[i], path, summary, match_index, levels.size()))
      entries[name] = std::move(*entry);
  }
  Json out = {{"table", table},
              {"level", (*match)["level"]},
              {"ladder_commit", commit},
              {"observables", entries}};
  // What the ladder refined, when not the whole grid (a graded grid's box: its GCI is the error
  // of the box's cells alone; campaigns/study/ladder.py writes it).
  if (doc.contains("scope")) out["scope"] = string_at(doc, "scope", "");
  return out;
}

}  // namespace

fs::path ladder_table_path(const fs::path& scene_file) {
  return scene_file.parent_path() / (scene_file.stem().string() + ".ladder.json");
}

Json discretization_error_of(const std::string& table, const std::string& text,
                             const std::string& fingerprint, const Json& summary) {
  const auto unreadable = [&](const std::string& why) {
    return Json{{"table", table}, {"status", "unreadable: " + why}};
  };
  try {
    const Json doc = Json::parse(text);
    return from_table(table, doc, fingerprint, summary);
  } catch (const Unreadable& e) {
    return unreadable(e.what());
  } catch (const Json::parse_error& e) {
    return unreadable(std::string("not JSON (") + e.what() + ")");
  } catch (const std::exception& e) {  // anything else the table provokes: still no failure
    return unreadable(e.what());
  }
}

std::optional<Json> discretization_error(const std::string& scene_file,
                                         const std::string& fingerprint, const Json& summary) {
  if (scene_file.empty()) return std::nullopt;
  fs::path table;
  try {
    table = ladder_table_path(scene_file);
    std::error_code ec;
    if (!fs::exists(table, ec)) return std::nullopt;
  } catch (const std::exception&) {  // a path the filesystem refuses: no table there
    return std::nullopt;
  }
  const auto unreadable = [&](const std::string& why) {
    return Json{{"table", table.string()}, {"status", "unreadable: " + why}};
  };
  try {
    std::error_code ec;
    if (!fs::is_regular_file(table, ec)) return unreadable("not a regular file");
    std::ifstream in(table, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in || in.bad()) return unreadable("cannot read the file");
    return discretization_error_of(table.string(), text, fingerprint, summary);
  } catch (const std::exception& e) {
    return unreadable(std::string("cannot read the file (") + e.what() + ")");
  }
}

}  // namespace impact::mpm
