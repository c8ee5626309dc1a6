#include "models/core/input_keys.hpp"

#include <algorithm>

namespace impact {

namespace {

std::vector<InputKey>::iterator find_path(std::vector<InputKey>& keys, std::string_view path) {
  return std::find_if(keys.begin(), keys.end(), [&](const InputKey& k) { return k.path == path; });
}

}  // namespace

void InputKeyRecorder::record(std::string_view path, KeyDescription description) {
  if (find_path(keys_, path) != keys_.end()) return;
  keys_.push_back({std::string(path), std::move(description)});
}

KeyDescription* InputKeyRecorder::find(std::string_view path) {
  const auto it = find_path(keys_, path);
  return it == keys_.end() ? nullptr : &it->description;
}

std::string dotted_key(std::string_view pointer, std::string_view wildcard) {
  std::string out;
  std::size_t start = pointer.empty() || pointer[0] != '/' ? 0 : 1;
  while (start <= pointer.size()) {
    const std::size_t slash = std::min(pointer.find('/', start), pointer.size());
    const std::string_view part = pointer.substr(start, slash - start);
    if (!out.empty()) out += '.';
    out += part == wildcard ? std::string("<name>") : std::string(part);
    start = slash + 1;
  }
  return out;
}

std::string keys_markdown(const std::vector<InputKey>& keys, std::string_view wildcard) {
  // A "|" inside a cell would split it.
  const auto cell = [](std::string text) {
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
      text.replace(at, 1, "\\|");
    return text;
  };
  std::string out = "| key | type | range | default | meaning |\n|---|---|---|---|---|\n";
  for (const InputKey& k : keys) {
    const KeyDescription& d = k.description;
    const std::string fallback = !d.default_value           ? "**required**"
                                 : d.default_value->empty() ? "none"
                                                            : "`" + *d.default_value + "`";
    out += "| `" + dotted_key(k.path, wildcard) + "` | " + cell(d.type) + " | " + cell(d.range) +
           " | " + cell(fallback) + " | " + cell(d.meaning) + " |\n";
  }
  return out;
}

nlohmann::json keys_json(const std::vector<InputKey>& keys, std::string_view wildcard) {
  nlohmann::json out = nlohmann::json::array();
  for (const InputKey& k : keys) {
    const KeyDescription& d = k.description;
    out.push_back({{"key", dotted_key(k.path, wildcard)},
                   {"pointer", k.path},
                   {"type", d.type},
                   {"range", d.range},
                   {"required", !d.default_value.has_value()},
                   {"default", d.default_value ? nlohmann::json(*d.default_value) : nullptr},
                   {"meaning", d.meaning}});
  }
  return out;
}

}  // namespace impact
