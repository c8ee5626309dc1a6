// A scene document: its `extends` chain merged (RFC 7396), material paths made relative to the
// file that names them, and where each key came from (for messages).
#include <filesystem>

#include "mpm/input/block_readers.hpp"

namespace impact::mpm {

namespace fs = std::filesystem;

namespace {

// Relative material paths in a file are relative to that file; rewrite them before merging so a
// base scene reached through `extends` keeps pointing at its own materials.
void resolve_material_paths(Json& doc, const fs::path& dir) {
  if (!doc.is_object() || !doc.contains("materials") || !doc["materials"].is_object()) return;
  for (auto& item : doc["materials"].items()) {
    Json& m = item.value();
    if (!m.is_object() || !m.contains("file") || !m["file"].is_string()) continue;
    const fs::path p(m["file"].get<std::string>());
    if (p.is_relative()) m["file"] = (dir / p).lexically_normal().string();
  }
}

// "a.json -> b.json -> a.json": the files of an extends chain, as they were reached.
std::string chain_text(const std::vector<std::string>& chain, const std::string& last) {
  std::string text;
  for (const auto& f : chain) text += f + " -> ";
  return text + last;
}

// `chain` holds the files that extend this one (outermost first), to detect cycles.
Json load_with_extends(const std::string& file, std::vector<std::string>& chain,
                       ExtendsChain* layers) {
  constexpr std::size_t kMaxDepth = 16;
  Json doc = load_json_file(file);
  if (!doc.is_object()) throw InputError({file + ": expected a JSON object (a scene)"});
  const fs::path dir = fs::path(file).parent_path();
  resolve_material_paths(doc, dir);
  if (!doc.contains("extends")) {
    if (layers != nullptr) layers->emplace_back(file, doc);
    return doc;
  }
  if (!doc["extends"].is_string()) {
    throw InputError({file + ": /extends: expected a string (path of the base scene), got " +
                      doc["extends"].dump()});
  }
  const std::string named = doc["extends"].get<std::string>();
  const fs::path base_path = fs::path(named).is_relative() ? dir / named : fs::path(named);
  const std::string base = base_path.lexically_normal().string();
  std::error_code ec;
  if (const auto kind = not_a_regular_file(base_path.string())) {
    // A FIFO or a device (/dev/zero) would block or stream forever: refused unread.
    throw InputError(
        {file + ": /extends: the base scene '" + named + "' " + *kind + "; expected a scene file"});
  }
  if (!fs::is_regular_file(base_path, ec)) {
    throw InputError({file + ": /extends: cannot open the base scene '" + named + "' (looked for " +
                      base + ", relative to the file that names it)"});
  }
  chain.push_back(file);
  const fs::path canonical_base = fs::weakly_canonical(base_path, ec);
  for (const auto& f : chain) {
    if (fs::weakly_canonical(f, ec) == canonical_base) {
      throw InputError({file + ": /extends: circular extends: " + chain_text(chain, base)});
    }
  }
  if (chain.size() > kMaxDepth) {
    throw InputError({file + ": /extends: expected at most " + std::to_string(kMaxDepth) +
                      " levels of extends: " + chain_text(chain, base)});
  }
  Json merged = load_with_extends(base, chain, layers);
  chain.pop_back();
  doc.erase("extends");
  if (layers != nullptr) layers->emplace_back(file, doc);
  merged.merge_patch(doc);  // RFC 7396: objects merge key by key, null deletes, arrays replace
  return merged;
}

}  // namespace

Json load_scene_document(const std::string& file, ExtendsChain* chain) {
  std::vector<std::string> extending;
  return load_with_extends(file, extending, chain);
}

void resolve_patch_material_paths(Json& patch) {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (!ec) resolve_material_paths(patch, cwd);
}

PatchOrigins extends_origins(const ExtendsChain& chain) {
  std::vector<Json> documents;
  for (const auto& layer : chain) documents.push_back(layer.second);
  const std::string file = chain.empty() ? std::string() : chain.back().first;
  return PatchOrigins(
      file, documents,
      [&](std::size_t k) {
        return k + 1 == chain.size() ? std::string()
                                     : chain[k].first + " (extended by " + file + ")";
      },
      /*over_file=*/false);
}

}  // namespace impact::mpm
