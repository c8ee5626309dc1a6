// pointdriver verify: the verification suite (verify/verification_suite.hpp): a table of checks
// on stdout, DIR/verification.csv, the figure data CSVs and, when python3 + matplotlib are there,
// the figures (PNG) drawn by pointdriver/plot/plot.py.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "pointdriver/commands/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/format/text_format.hpp"
#include "pointdriver/output/junit.hpp"
#include "pointdriver/plot/plot_script.hpp"
#include "pointdriver/verify/verification_suite.hpp"
#include "support/atomic_file.hpp"

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

const CommandSpec verify_command{
    "verify",
    "Runs the point driver's verification suite: each case drives the material along paths\n"
    "built in code and compares with references derived independently (closed forms, integrals\n"
    "of the driver's own rows), with a stated tolerance. Prints the table (case, quantity,\n"
    "expected, got, error, tolerance, pass), writes it to DIR/verification.csv with the figure\n"
    "data (CSV) of the cases and, when python3 and matplotlib are installed, the figures (PNG).\n"
    "expected and got are in the SI unit of the quantity named (Pa, K, J/kg, m/s; strains and\n"
    "ratios [-]); error and tolerance are dimensionless (relative, or in the unit the quantity\n"
    "names, e.g. \"error / max |sigma|\").",
    "", 0,
    "Exit codes: 0 all checks pass, 1 usage error, 3 a check failed (a figure data file that\n"
    "cannot be written fails its case) or an output (a figure too, or a full stdout) could not\n"
    "be written, 141 stdout closed by its reader (| head).\n"};

std::string fmt(double v, const char* f = "%.6g") {
  char buf[40];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

/// The header cells of a CSV (names without units), or none when it cannot be read.
std::vector<std::string> csv_header(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> names;
  if (!std::getline(in, line)) return names;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) names.push_back(c.substr(0, c.find(" [")));
  return names;
}

struct Figure {
  std::string png;
  std::vector<std::string> csvs;
  std::string x;
  std::vector<std::string> y;  ///< columns; a trailing '*' selects every column with that prefix
  std::string title;
  std::vector<std::string> labels;
  std::string ylabel;                    ///< the quantity on the y axis (plot.py adds the unit)
  std::string style_by;                  ///< plot.py --style-by: a line style per match, else none
  std::vector<std::string> points = {};  ///< CSVs of measurements, drawn as points
};

const std::vector<Figure>& figures() {
  static const std::vector<Figure> list = {
      {"johnson_cook_flow_curves.png",
       {"johnson_cook_flow_curves.csv"},
       "log_strain_xx",
       {"driver_*"},
       "Johnson-Cook uniaxial stress, 4 rates x 3 temperatures",
       {},
       "axial stress sigma_xx",
       "[0-9]+K"},
      {"adiabatic_compression_stress.png",
       {"adiabatic_compression.csv"},
       "plastic_strain",
       {"von_mises"},
       "Adiabatic compression at 4000 /s: Drucker fires at the maximum",
       {},
       "von Mises stress",
       ""},
      {"adiabatic_compression_temperature.png",
       {"adiabatic_compression.csv"},
       "plastic_strain",
       {"temperature", "temperature_reference"},
       "Adiabatic heating: driver vs chi int sigma d eps_p / (rho cp)",
       {},
       "temperature",
       ""},
      {"simple_shear.png",
       {"simple_shear.csv"},
       "gamma",
       {"green_naghdi_xy", "dienes_xy", "jaumann_xy", "mu_sin_gamma"},
       "Simple shear: Green-Naghdi vs Dienes (1979), Jaumann oscillates",
       {},
       "shear stress sigma_xy",
       ""},
      {"mie_gruneisen_hugoniot.png",
       {"mie_gruneisen_path.csv", "mie_gruneisen_hugoniot.csv",
        "mie_gruneisen_hugoniot_experiments.csv"},
       "volume_ratio",
       {"pressure"},
       "Mie-Gruneisen uniaxial strain vs the Hugoniot and experiments",
       {"driver path", "Hugoniot (closed form)", "experiments (McQueen, Mitchell, Vaidya)"},
       "pressure",
       "",
       {"mie_gruneisen_hugoniot_experiments.csv"}},
  };
  return list;
}

/// Draws the figures whose data exist; says so once when plotting is not possible. False when a
/// figure could not be written (plot.py said which and why).
bool draw_figures(const fs::path& out) {
  for (const Figure& f : figures()) {
    std::vector<std::string> args;
    std::vector<std::string> labels;
    for (std::size_t i = 0; i < f.csvs.size(); ++i) {
      if (!fs::exists(out / f.csvs[i])) continue;
      args.push_back((out / f.csvs[i]).string());
      if (i < f.labels.size()) labels.push_back(f.labels[i]);
    }
    if (args.empty()) continue;
    args.insert(args.end(), {"--x", f.x});
    for (const std::string& y : f.y) {
      if (!y.empty() && y.back() == '*') {
        const std::string prefix = y.substr(0, y.size() - 1);
        for (const std::string& name : csv_header(args.front())) {
          if (name.rfind(prefix, 0) == 0) args.insert(args.end(), {"--y", name});
        }
      } else {
        args.insert(args.end(), {"--y", y});
      }
    }
    // Legend labels only when every file of the figure is present (one label per file).
    if (labels.size() == f.labels.size() && !labels.empty()) {
      for (const std::string& l : labels) args.insert(args.end(), {"--label", l});
    }
    args.insert(args.end(), {"--title", f.title, "--ylabel", f.ylabel});
    if (!f.style_by.empty()) args.insert(args.end(), {"--style-by", f.style_by});
    for (const std::string& csv : f.points) {
      if (fs::exists(out / csv)) args.insert(args.end(), {"--points", (out / csv).string()});
    }
    args.insert(args.end(), {"-o", (out / f.png).string()});
    const PlotRun r = run_plot_script(args, false);
    if (r.status == PlotRun::Status::no_python || r.status == PlotRun::Status::no_matplotlib ||
        r.status == PlotRun::Status::no_script) {
      std::cout << "figures skipped (" << r.message << "); the figure data are in " << out.string()
                << '\n';
      return true;
    }
    if (r.status != PlotRun::Status::ok) {
      if (!said_why(r)) {
        std::cerr << "pointdriver verify: figure " << (out / f.png).string()
                  << " not drawn: " << r.message << '\n';
      }
      return false;
    }
  }
  return true;
}

}  // namespace

int command_verify(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code =
          parse_command(verify_command, o, args,
                        {{"-o|--out", 1, "output directory (default: pointdriver_verify)", "DIR"},
                         {"--case", 1, "run only this case (repeatable)", "NAME"},
                         {"--list", 0, "print the case names"},
                         {"--junit", 1, "one JUnit test case per check", "FILE"}})) {
    return *exit_code;
  }
  const auto& cases = verification_cases();
  if (o.has("--list")) {
    for (const auto& c : cases) std::cout << c.name << "  " << c.description << '\n';
    return 0;
  }
  std::vector<const VerificationCase*> selected;
  for (const std::string& name : o.all("--case")) {
    const VerificationCase* found = nullptr;
    for (const auto& c : cases) {
      if (c.name == name) found = &c;
    }
    if (!found) {
      std::cerr << "pointdriver verify: unknown case '" << name << "'; known:";
      for (const auto& c : cases) std::cerr << ' ' << c.name;
      std::cerr << '\n';
      return 1;
    }
    selected.push_back(found);
  }
  if (selected.empty()) {
    for (const auto& c : cases) selected.push_back(&c);
  }

  const fs::path out = o.get("--out", "pointdriver_verify");
  try {
    create_output_directory(out);
  } catch (const OutputError& e) {
    std::cerr << "pointdriver verify: " << e.what() << '\n';
    return cli::kExitFailed;
  }
  const SuiteContext ctx = default_suite_context(out.string());

  std::vector<Check> all;
  int failed = 0;
  std::cout << "pass  case / quantity\n      expected | got | error | tolerance\n";
  for (const VerificationCase* c : selected) {
    const std::vector<Check> checks = run_case(*c, ctx);
    for (const Check& k : checks) {
      std::cout << (k.pass ? "ok    " : "FAIL  ") << k.case_name << ": " << k.quantity << "\n      "
                << fmt(k.expected, "%.10g") << " | " << fmt(k.got, "%.10g") << " | "
                << fmt(k.error, "%.3g") << " | " << fmt(k.tolerance, "%.3g") << '\n';
      failed += k.pass ? 0 : 1;
      all.push_back(k);
    }
  }

  const fs::path table = out / "verification.csv";
  try {
    write_file_atomically(table, [&](std::ostream& csv) {
      csv << "case,quantity,expected [SI],got [SI],error [-],tolerance [-],pass\n";
      for (const Check& k : all) {
        csv << csv_cell(k.case_name) << ',' << csv_cell(k.quantity) << ','
            << fmt(k.expected, "%.15g") << ',' << fmt(k.got, "%.15g") << ',' << fmt(k.error, "%.6g")
            << ',' << fmt(k.tolerance, "%.6g") << ',' << (k.pass ? "yes" : "no") << '\n';
      }
    });
  } catch (const OutputError& e) {
    std::cerr << "pointdriver verify: " << e.what() << '\n';
    return cli::kExitFailed;
  }
  if (o.has("--junit")) {
    std::vector<JunitCase> junit;
    for (const Check& k : all) {
      const std::string compared = "expected " + fmt(k.expected, "%.10g") + ", got " +
                                   fmt(k.got, "%.10g") + ", error " + fmt(k.error, "%.3g") +
                                   ", tolerance " + fmt(k.tolerance, "%.3g");
      junit.push_back({k.quantity, "verify." + k.case_name, 0.0,
                       k.pass ? std::nullopt : std::optional(compared), compared});
    }
    try {
      write_junit(o.get("--junit", ""), "pointdriver verify", junit);
    } catch (const std::runtime_error& e) {
      std::cerr << "pointdriver verify: " << e.what() << '\n';
      return cli::kExitFailed;
    }
  }
  const bool drawn = draw_figures(out);
  std::cout << all.size() - static_cast<std::size_t>(failed) << " of " << all.size()
            << " checks pass; table in " << table.string() << '\n';
  return failed == 0 && drawn ? 0 : 3;
}

}  // namespace impact::pointdriver
