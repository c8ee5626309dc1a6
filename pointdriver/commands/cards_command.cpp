// pointdriver cards MATERIAL.json: a Johnson-Cook or Swift x Cowper-Symonds material (a fitted
// one, typically) as LS-DYNA and Abaqus cards in a consistent unit system
// (pointdriver/export/solver_cards.hpp).
#include <filesystem>
#include <fstream>
#include <iostream>

#include "pointdriver/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/export/solver_cards.hpp"

namespace impact::pointdriver {

namespace {

namespace fs = std::filesystem;

const CommandSpec cards_command{
    "cards",
    "Writes a Johnson-Cook material as LS-DYNA *MAT_JOHNSON_COOK with its *EOS card and as an\n"
    "Abaqus *MATERIAL block (*PLASTIC, HARDENING=JOHNSON COOK; *RATE DEPENDENT), or a Swift x\n"
    "Cowper-Symonds (cowper_symonds) material as *MAT_POWER_LAW_PLASTICITY and an Abaqus block\n"
    "with tabulated *PLASTIC and *RATE DEPENDENT, TYPE=POWER LAW, in a consistent unit system\n"
    "(docs/fitting.md): SI (m, kg, s: Pa; the default), mm-s-tonne (MPa), mm-ms-kg (GPa) or\n"
    "mm-ms-g (MPa); temperatures in K. Prints both; with --out DIR writes DIR/<material>.k and\n"
    "DIR/<material>.inp instead.",
    "MATERIAL.json", 1,
    "Exit codes: 0 done, 1 usage, 2 input error (a bad material, another law, an unknown unit\n"
    "system).\n"};

}  // namespace

int command_cards(const std::vector<std::string>& args) {
  Options o;
  if (const auto exit_code = parse_command(
          cards_command, o, args,
          {{"--units", 1, "SI (default), mm-s-tonne, mm-ms-kg or mm-ms-g", "SYSTEM"},
           {"-o|--out", 1, "write the cards into DIR instead of printing them", "DIR"},
           {"--set", 1, "JSON merge patch over the material (repeatable)", "JSON"}})) {
    return *exit_code;
  }
  if (o.positional.size() != 1) {
    std::cerr << "pointdriver cards: expected one MATERIAL.json (pointdriver cards --help)\n";
    return 1;
  }
  try {
    const UnitSystem& units = unit_system(o.get("--units", "SI"));
    const Material material = load_material(o.positional[0], cli::patches_of(o.all("--set")));
    if (o.verbosity.verbose) std::cerr << to_json(material).dump(2) << '\n';
    const std::string dyna = ls_dyna_cards(material, units);
    const std::string abaqus = abaqus_cards(material, units);
    if (!o.has("--out")) {
      std::cout << dyna << '\n' << abaqus;
      return 0;
    }
    const fs::path dir = o.get("--out", ".");
    fs::create_directories(dir);
    const std::string stem = fs::path(o.positional[0]).stem().string();
    std::ofstream(dir / (stem + ".k")) << "*KEYWORD\n" << dyna << "*END\n";
    std::ofstream(dir / (stem + ".inp")) << abaqus;
    std::cout << "wrote " << (dir / (stem + ".k")).string() << ", "
              << (dir / (stem + ".inp")).string() << " (units " << units.name << ")\n";
    return 0;
  } catch (const InputError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  } catch (const Json::parse_error& e) {
    std::cerr << "pointdriver cards: --set: not JSON: " << e.what() << '\n';
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "pointdriver cards: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace impact::pointdriver
