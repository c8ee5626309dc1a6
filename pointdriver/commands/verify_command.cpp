#include "pointdriver/commands.hpp"
namespace impact::pointdriver {
int command_verify(const std::vector<std::string>&) {
  return 1;
}
}  // namespace impact::pointdriver
