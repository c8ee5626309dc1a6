// Path documents for the point driver's unit tests, built in code around the 6061-T6 file.
#pragma once

#include <string>
#include <vector>

#include "pointdriver/driver/driver.hpp"
#include "pointdriver/path/path.hpp"

namespace impact::pointdriver::testing {

inline std::string material_file() {
  return std::string(IMPACT_SOURCE_DIR) + "/data/materials/al6061_t6.json";
}

/// {"material": {file, overrides}, "temperature": 294, "legs": legs} plus `extra` merged in.
inline Json document(const Json& legs, const Json& overrides = Json::object(),
                     const Json& extra = Json::object()) {
  Json d = {{"material", {{"file", material_file()}, {"overrides", overrides}}},
            {"temperature", 294.0},
            {"legs", legs.is_array() ? legs : Json::array({legs})}};
  d.merge_patch(extra);
  return d;
}

struct Rows {
  RunResult result;
  std::vector<Row> rows;
};

inline Rows run_document(const Json& doc) {
  Rows r;
  const Path path = read_path(doc, "test path");
  r.result = run_path(path, [&](const Row& row) { r.rows.push_back(row); });
  return r;
}

}  // namespace impact::pointdriver::testing
