#include "pointdriver/commands.hpp"
namespace impact::pointdriver {
int command_convergence(const std::vector<std::string>&) {
  return 1;
}
}  // namespace impact::pointdriver
