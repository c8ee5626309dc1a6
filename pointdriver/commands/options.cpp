#include "pointdriver/commands/options.hpp"

#include <sstream>

namespace impact::pointdriver {

namespace {

std::vector<std::string> aliases(const std::string& name) {
  std::vector<std::string> out;
  std::stringstream ss(name);
  for (std::string a; std::getline(ss, a, '|');) out.push_back(a);
  return out;
}

}  // namespace

std::string Options::get(const std::string& name, const std::string& fallback) const {
  const auto it = values.find(name);
  return it == values.end() || it->second.empty() ? fallback : it->second.back();
}

const std::vector<std::string>& Options::all(const std::string& name) const {
  static const std::vector<std::string> none;
  const auto it = values.find(name);
  return it == values.end() ? none : it->second;
}

Json patched_json_file(const std::string& file, const std::vector<Json>& patches) {
  Json document = load_json_file(file);
  for (const auto& p : patches) document.merge_patch(p);
  return document;
}

std::optional<int> parse_command(const CommandSpec& command, Options& out,
                                 const std::vector<std::string>& args,
                                 const std::vector<OptionSpec>& specs) {
  CLI::App app{command.description, "pointdriver " + command.name};
  // Every option's words, by its last alias; flags count their occurrences.
  std::map<std::string, std::vector<std::string>> words;
  std::map<std::string, std::int64_t> flags;
  for (const auto& s : specs) {
    const auto names = aliases(s.name);
    std::string cli_names;
    for (const auto& n : names) cli_names += (cli_names.empty() ? "" : ",") + n;
    const std::string key = names.back();
    if (s.arity == 0) {
      app.add_flag(cli_names, flags[key], s.help);
    } else {
      CLI::Option* o = app.add_option(cli_names, words[key], s.help)->type_name(s.value_name);
      // One value per occurrence, repeatable (--y a --y b): the help then reads `--y COL`, not
      // `COL ...`, which promised `--y a b` (taken as --y a and a file b).
      if (s.arity == 1)
        o->allow_extra_args(false)->expected(1)->multi_option_policy(
            CLI::MultiOptionPolicy::TakeAll);
      if (key == "--set") o->check(cli::set_patch_error, "");
    }
  }
  if (command.max_positional > 0) {
    app.add_option(command.positional, out.positional)
        ->expected(0, static_cast<int>(command.max_positional));
  }
  cli::describe(app, command.footer, out.verbosity);
  if (const auto code = cli::parse(app, args, out.verbosity)) return code;
  for (auto& [key, v] : words) {
    if (!v.empty()) out.values[key] = v;
  }
  for (const auto& [key, count] : flags) {
    if (count > 0) out.values[key] = std::vector<std::string>(static_cast<std::size_t>(count), "1");
  }
  return std::nullopt;
}

}  // namespace impact::pointdriver
