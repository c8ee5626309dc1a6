// pointdriver cards MATERIAL.json: a Johnson-Cook or Swift x Cowper-Symonds material (a fitted
// one, typically) as LS-DYNA and Abaqus cards in a consistent unit system
// (pointdriver/export/solver_cards.hpp).
#include <filesystem>
#include <iostream>

#include "pointdriver/commands/commands.hpp"
#include "pointdriver/commands/options.hpp"
#include "pointdriver/export/solver_cards.hpp"
#include "support/atomic_file.hpp"

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
    "system), 3 a card file (or stdout) could not be written.\n"};

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
  std::vector<Json> patches;
  const std::string& file = o.positional[0];
  try {
    const UnitSystem& units = unit_system(o.get("--units", "SI"));
    patches = cli::patches_of(o.all("--set"));
    const Material material = load_material(file, patches);
    if (o.verbosity.verbose) std::cerr << to_json(material).dump(2) << '\n';
    const std::string dyna = ls_dyna_cards(material, units);
    const std::string abaqus = abaqus_cards(material, units);
    if (!o.has("--out")) {
      std::cout << dyna << '\n' << abaqus;  // checked by main (stdout_checked)
      return 0;
    }
    const fs::path dir = o.get("--out", ".");
    create_output_directory(dir);
    const std::string stem = fs::path(file).stem().string();
    // Both written before either is renamed into place: a failure leaves the previous pair.
    AtomicFile k(dir / (stem + ".k")), inp(dir / (stem + ".inp"));
    k.stream() << "*KEYWORD\n" << dyna << "*END\n";
    inp.stream() << abaqus;
    for (AtomicFile* f : {&k, &inp}) {
      f->stream().flush();
      f->check();
    }
    k.commit();
    inp.commit();
    std::cout << "wrote " << (dir / (stem + ".k")).string() << ", "
              << (dir / (stem + ".inp")).string() << " (units " << units.name << ")\n";
    return 0;
  } catch (const InputError& e) {
    std::cerr << cli::set_origins(file, patches).attribute(e).what() << '\n';
    return cli::kExitInput;
  } catch (const std::invalid_argument& e) {  // a value the cards cannot hold (Swift's SIGY)
    std::cerr << "pointdriver cards: " << cli::set_origins(file, patches).attribute(e.what())
              << '\n';
    return cli::kExitInput;
  } catch (const OutputError& e) {
    std::cerr << "pointdriver cards: " << e.what() << '\n';
    return cli::kExitFailed;
  }
}

}  // namespace impact::pointdriver
