// The point driver's commands; each parses its own options (unknown ones are rejected), prints
// its own --help and returns the process exit code (see main.cpp).
#pragma once

#include <string>
#include <vector>

namespace impact::pointdriver {

int command_run(const std::vector<std::string>& args);
int command_verify(const std::vector<std::string>& args);
int command_batch(const std::vector<std::string>& args);
int command_convergence(const std::vector<std::string>& args);
int command_fit(const std::vector<std::string>& args);
int command_check(const std::vector<std::string>& args);
int command_cards(const std::vector<std::string>& args);
int command_plot(const std::vector<std::string>& args);

}  // namespace impact::pointdriver
