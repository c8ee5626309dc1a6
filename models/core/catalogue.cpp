#include "models/core/catalogue.hpp"

#include <stdexcept>

namespace impact {

void throw_no_such_parameter(std::string_view type, std::string_view name,
                             const std::vector<std::string>& known) {
  std::string list;
  for (const std::string& n : known) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument(std::string(type) + " has no parameter " + std::string(name) +
                              " (it has " + (list.empty() ? "none" : list) + ")");
}

}  // namespace impact
