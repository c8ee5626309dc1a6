#include "pointdriver/commands.hpp"
namespace impact::pointdriver {
int command_plot(const std::vector<std::string>&, const char*) {
  return 1;
}
}  // namespace impact::pointdriver
