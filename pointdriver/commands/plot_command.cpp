// pointdriver plot: a quick figure from one or more run CSV files, drawn by plot.py (matplotlib).
#include <filesystem>
#include <iostream>
#include <limits>

#include "pointdriver/commands/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/plot/plot_script.hpp"

namespace impact::pointdriver {

namespace {

const CommandSpec plot_command{
    "plot",
    "Draws --y against --x from point-driver CSV files (one line per file and y column; several\n"
    "files are overlaid with a legend, labelled by file name or by --label, one per file).\n"
    "Columns are named as in the CSV header, with or without the unit: `stress_xx` matches\n"
    "`stress_xx [Pa]`; axis labels show the units, and y columns of different units go on\n"
    "separate panels sharing x (one per unit); stresses in MPa or GPa. The figure format\n"
    "follows -o (.png, .pdf, .svg; another name is a usage error) and the figure is written\n"
    "whole or not at all. Needs python3 and matplotlib (Debian: apt-get install -y\n"
    "python3-matplotlib); the script is pointdriver/plot/plot.py (installed under\n"
    "share/impact), or $POINTDRIVER_PLOT_SCRIPT; the interpreter $IMPACT_PYTHON, else the\n"
    "first of /usr/bin/python3 and python3 that has matplotlib.",
    "CSV", std::numeric_limits<std::size_t>::max(),
    "Exit codes: 0 done, 1 usage error or python3/matplotlib missing, 2 input error, 3 the\n"
    "figure or stdout could not be written, 130 Ctrl-C, 141 stdout closed by its reader.\n"};

}  // namespace

int command_plot(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code =
          parse_command(plot_command, o, args,
                        {{"--x", 1, "column of the x axis", "COL"},
                         {"--y", 1, "column of a y series (repeatable)", "COL"},
                         {"-o|--out|--output", 1, "figure file (.png, .pdf, .svg)", "FIG"},
                         {"--title", 1, "figure title", "TEXT"},
                         {"--logx", 0, "logarithmic x axis"},
                         {"--logy", 0, "logarithmic y axis"},
                         {"--label", 1, "legend label, one per CSV file (repeatable)", "NAME"}})) {
    return *exit_code;
  }
  std::string missing;
  if (o.positional.empty()) missing = "a CSV file";
  if (!o.has("--x")) missing = "--x COL";
  if (!o.has("--y")) missing = "--y COL";
  if (!o.has("--output")) missing = "-o FIG.png";
  if (!missing.empty()) {
    std::cerr << "pointdriver plot: missing " << missing << " (pointdriver plot --help)\n";
    return 1;
  }
  if (o.has("--x") && o.all("--x").size() > 1) {
    std::cerr << "pointdriver plot: --x given more than once\n";
    return 1;
  }
  if (o.has("--label") && o.all("--label").size() != o.positional.size()) {
    std::cerr << "pointdriver plot: give --label once per CSV file (" << o.positional.size()
              << " files, " << o.all("--label").size() << " labels)\n";
    return 1;
  }
  for (const auto& f : o.positional) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(f, ec)) {
      const char* why = std::filesystem::is_directory(f, ec) ? "is a directory. expected a CSV file"
                        : std::filesystem::exists(f, ec)     ? "is not a regular file"
                                                             : "no such file";
      std::cerr << "pointdriver plot: " << f << ": " << why << '\n';
      return 2;
    }
  }
  std::vector<std::string> a = o.positional;
  // `--key=value` so that values starting with '-' reach argparse intact.
  a.push_back("--x=" + o.get("--x", ""));
  a.push_back("--output=" + o.get("--output", ""));
  for (const auto& y : o.all("--y")) a.push_back("--y=" + y);
  for (const auto& l : o.all("--label")) a.push_back("--label=" + l);
  if (o.has("--title")) a.push_back("--title=" + o.get("--title", ""));
  if (o.has("--logx")) a.push_back("--logx");
  if (o.has("--logy")) a.push_back("--logy");
  const PlotRun r = run_plot_script(a);
  if (r.status != PlotRun::Status::ok && !said_why(r))
    std::cerr << "pointdriver plot: " << r.message << '\n';
  return plot_exit_code(r);
}

}  // namespace impact::pointdriver
