// Which merge patch a problem comes from. The programs' --set patches (and the Python module's
// `patches`) are merged into a file's document before it is read, so a reader reports a bad
// patched value as the file's ("scene.json: /time/multiplier: expected ..."). PatchOrigins puts
// the patch in front instead ("--set patch 1 (over scene.json): /time/multiplier: expected ...")
// when the last patch that touched the key set that key, one above it or one below it. A problem
// at a material reference ("/materials/al/file: in material al.json: /density: ...") is the
// patch's when the patch set that material's overrides at the same key (.../overrides/density).
// An unknown key in a block whose "type" a later patch set (later than the one that set the key,
// or than the file) is that patch's too: the new type does not take it, and the patch can delete
// it.
// The files of a scene's extends chain are merge patches too: a problem at a key a base scene
// set names that base (mpm/input/scene_reader.hpp extends_origins).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "models/core/input.hpp"

namespace impact {

class PatchOrigins {
 public:
  /// `patches` as merged over `file` (in order); `name(k)` is what messages call patch k. With
  /// `over_file` a message names "NAME (over FILE)", else NAME alone; a patch named "" leaves the
  /// message as it is (a scene's own document, last of its extends chain).
  PatchOrigins(std::string file, const std::vector<Json>& patches,
               const std::function<std::string(std::size_t)>& name, bool over_file = true)
      : file_(std::move(file)), over_file_(over_file) {
    for (std::size_t k = 0; k < patches.size(); ++k) {
      std::vector<std::pair<std::string, Json>> keys;
      leaves(patches[k], "", keys);
      for (auto& [key, value] : keys)
        set_.push_back({std::move(key), name(k), k, std::move(value)});
    }
  }

  /// "FILE: /key: ..." (or "warning: FILE: /key: ...") with FILE replaced by "NAME (over FILE)"
  /// when a patch set /key (the last such patch); any other message as it is.
  std::string attribute(const std::string& message) const {
    static const std::string kWarning = "warning: ";
    const bool warning = message.rfind(kWarning, 0) == 0;
    const std::string head = (warning ? kWarning : "") + file_ + ": /";
    if (set_.empty() || message.rfind(head, 0) != 0) return message;
    const std::size_t key_start = head.size() - 1;
    const std::size_t key_end = message.find(": ", key_start);
    if (key_end == std::string::npos) return message;
    std::string key = message.substr(key_start, key_end - key_start);
    if (key == "/") key.clear();
    const std::string rest = message.substr(key_end + 2);
    const std::string* patch = nullptr;
    std::size_t after = 0;  // the patches after the last one that set the key
    for (const Set& set : set_) {
      if (on_one_branch(key, set.key) || on_one_branch(override_key(key, rest), set.key)) {
        patch = &set.name;
        after = set.patch + 1;
      }
    }
    // A key left without a meaning by a later patch that changed its block's type: that patch's
    // doing (not the file's, or the base scene's that set the key), and that patch can delete it.
    const std::size_t leaf = key.rfind('/');
    std::string orphaned;
    if (leaf != std::string::npos && rest.rfind("unknown key", 0) == 0) {
      const std::string type = key.substr(0, leaf) + "/type";
      const Json* before = nullptr;  // the type as the layers up to the key's own left it
      for (const Set& set : set_)
        if (set.patch < after && set.key == type) before = &set.value;
      for (const Set& set : set_) {
        // A later layer that writes the same type again (a derived scene often repeats it)
        // leaves the key's meaning as it was: the key's own layer keeps its typo.
        if (set.patch < after || set.key != type || (before && set.value == *before)) continue;
        patch = &set.name;
        orphaned = "; the patch's type does not take it: delete it in the patch (\"" +
                   key.substr(leaf + 1) + "\": null)";
      }
    }
    if (patch == nullptr) return message;
    if (patch->empty()) return message + orphaned;
    return (warning ? kWarning : "") + *patch + (over_file_ ? " (over " + file_ + ")" : "") + ": " +
           message.substr(key_start) + orphaned;
  }

  InputError attribute(const InputError& error) const {
    return InputError(attribute(error.problems()));
  }

  std::vector<std::string> attribute(const std::vector<std::string>& messages) const {
    std::vector<std::string> out;
    for (const auto& m : messages) out.push_back(attribute(m));
    return out;
  }

 private:
  /// The key paths a merge patch sets, with their values: its non-object values (null deletes,
  /// an array replaces). Each key escaped as the messages write it (RFC 6901: ~ as ~0, / as ~1).
  static void leaves(const Json& patch, const std::string& at,
                     std::vector<std::pair<std::string, Json>>& out) {
    if (!patch.is_object() || (patch.empty() && !at.empty())) {
      out.emplace_back(at, patch);
      return;
    }
    for (const auto& [k, v] : patch.items()) leaves(v, at + "/" + pointer_token(k), out);
  }

  /// a == b, or one is a key above the other ("" only matches itself: a problem at the top of
  /// the document is not every patch's).
  static bool on_one_branch(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty()) return a == b;
    const auto below = [](const std::string& x, const std::string& above) {
      return x.size() > above.size() && x.compare(0, above.size(), above) == 0 &&
             x[above.size()] == '/';
    };
    return a == b || below(a, b) || below(b, a);
  }

  /// For "/X/file" (or "/X") + "in material M: /inner: ...": "/X/overrides/inner", the key a
  /// patch sets to change that value of the referenced material; else "".
  static std::string override_key(const std::string& key, const std::string& rest) {
    static const std::string kNested = "in material ";
    if (rest.rfind(kNested, 0) != 0) return "";
    const std::size_t inner = rest.find(": /", kNested.size());
    if (inner == std::string::npos) return "";
    const std::size_t inner_end = rest.find(": ", inner + 2);
    std::string owner = key;
    static const std::string kFile = "/file";
    if (owner.size() > kFile.size() &&
        owner.compare(owner.size() - kFile.size(), kFile.size(), kFile) == 0)
      owner.resize(owner.size() - kFile.size());
    return owner + "/overrides" + rest.substr(inner + 2, inner_end - (inner + 2));
  }

  std::string file_;
  bool over_file_ = true;
  struct Set {
    std::string key;    ///< the key path a patch set
    std::string name;   ///< the patch's name in messages
    std::size_t patch;  ///< its index, in merge order
    Json value;         ///< what it set there
  };
  std::vector<Set> set_;  ///< every key path each patch set, in merge order
};

}  // namespace impact
