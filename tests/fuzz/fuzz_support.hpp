// Shared pieces of the libFuzzer targets in tests/fuzz/ (one target per loader).
//
// The property every target checks: a loader given arbitrary bytes either returns a valid object
// or throws impact::InputError. Any other exception aborts the process (so libFuzzer records the
// input as a finding), and crashes, sanitizer reports, leaks and timeouts are findings by
// construction.
//
// The loaders read files and resolve references to other files (a scene's materials and
// `extends`, a path's or a fit's material, a fit's experiment files). Each input is therefore
// written to a file inside a scratch mirror of the repository's data/ folder, made once per
// process:
//   <scratch>/data/{materials,experiments,paths,fits}  -> links to the repository's folders
//   <scratch>/data/scenes/{sphere_cylinder,verification} -> links
//   <scratch>/data/scenes/fuzz/  links to every repository scene + the scene input file, so that
//                                "extends": "case01.json" and "../../materials/x.json" resolve
//   <scratch>/data/fuzz/         the other targets' input file; "data/materials/x.json" resolves
//                                through the loaders' parent-directory lookup
// Nothing is written to the repository. The scratch folder lives under $TMPDIR (or /tmp) and is
// removed at exit.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>

#include "models/core/input.hpp"

#ifndef IMPACT_SOURCE_DIR
#error "IMPACT_SOURCE_DIR must name the repository (set by tests/fuzz/CMakeLists.txt)"
#endif

namespace impact::fuzz {

namespace fs = std::filesystem;

/// The scratch mirror (created on first use, removed at exit). Never destroyed, so that the exit
/// handler can still use it.
inline const fs::path& scratch() {
  static const fs::path* const root = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/impact_fuzz_XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("impact fuzz: mkdtemp");
      std::abort();
    }
    const fs::path dir(pattern);
    const fs::path source = fs::path(IMPACT_SOURCE_DIR) / "data";
    fs::create_directories(dir / "data" / "scenes" / "fuzz");
    fs::create_directories(dir / "data" / "fuzz");
    for (const char* sub : {"materials", "experiments", "paths", "fits"}) {
      fs::create_directory_symlink(source / sub, dir / "data" / sub);
    }
    for (const char* sub : {"sphere_cylinder", "verification"}) {
      fs::create_directory_symlink(source / "scenes" / sub, dir / "data" / "scenes" / sub);
      for (const auto& entry : fs::directory_iterator(source / "scenes" / sub)) {
        fs::create_symlink(entry.path(),
                           dir / "data" / "scenes" / "fuzz" / entry.path().filename());
      }
    }
    std::atexit([] {
      std::error_code ec;
      fs::remove_all(scratch(), ec);  // removes the links, never what they point to
    });
    return new fs::path(dir);
  }();
  return *root;
}

/// Writes `data` to `relative` (inside the scratch mirror) and returns the file's path.
inline std::string write_input(std::string_view relative, const std::uint8_t* data,
                               std::size_t size) {
  const fs::path file = scratch() / relative;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "impact fuzz: cannot write %s\n", file.c_str());
    std::abort();
  }
  return file.string();
}

/// Runs `load`; an InputError is the expected way to refuse, anything else is a finding.
template <class Load>
void expect_value_or_input_error(const char* what, Load&& load) {
  try {
    load();
  } catch (const InputError&) {
    // A refusal with a message: the documented behaviour.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "impact fuzz: %s threw %s (not InputError): %s\n", what, typeid(e).name(),
                 e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "impact fuzz: %s threw a non-std exception\n", what);
    std::abort();
  }
}

}  // namespace impact::fuzz
