#include "mpm/run/scene_fingerprint.hpp"

#include <cstdio>

#include "mpm/output/checkpoint_stream.hpp"

namespace impact::mpm {

Json fingerprint_document(const Json& resolved) {
  Json doc = resolved;
  if (!doc.is_object()) return doc;
  // Of the output settings only those the observables depend on: the history interval (the
  // peaks are sampled at its rows) and the gauges' and crater's definitions. Where files go,
  // snapshots, fields and checkpoints change no number of the run.
  if (doc.contains("output") && doc["output"].is_object()) {
    Json kept = Json::object();
    for (const char* key : {"interval", "gauges", "crater"})
      if (doc["output"].contains(key)) kept[key] = doc["output"][key];
    doc["output"] = kept;
  } else {
    doc.erase("output");
  }
  doc.erase("description");
  if (!doc.contains("materials") || !doc["materials"].is_object()) return doc;
  for (auto& item : doc["materials"].items()) {
    Json& m = item.value();
    if (!m.is_object() || !m.contains("file") || !m["file"].is_string()) continue;
    Json content = load_json_file(m["file"].get<std::string>());
    // As load_material applies them: the values the run uses, wherever they were written.
    if (m.contains("overrides") && m["overrides"].is_object()) content.merge_patch(m["overrides"]);
    m = std::move(content);
  }
  return doc;
}

std::string scene_fingerprint(const Json& resolved) {
  const std::string text = fingerprint_document(resolved).dump();  // std::map: keys sorted
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(fnv1a(text.data(), text.size())));
  return hex;
}

}  // namespace impact::mpm
