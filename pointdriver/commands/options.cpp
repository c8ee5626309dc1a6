#include "pointdriver/commands/options.hpp"

#include <iostream>
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

Options parse_options(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                      std::size_t max_positional) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      o.help = true;
      continue;
    }
    if (a.size() > 1 && a[0] == '-') {
      const OptionSpec* spec = nullptr;
      std::string key;
      for (const auto& s : specs) {
        const auto names = aliases(s.name);
        for (const auto& n : names) {
          if (n == a) {
            spec = &s;
            key = names.back();
          }
        }
      }
      if (!spec) throw UsageError("unknown option '" + a + "'");
      auto& v = o.values[key];
      if (spec->arity == 0) {
        v.push_back("1");
      } else if (spec->arity == 1) {
        if (i + 1 >= args.size()) throw UsageError("option '" + a + "' needs a value");
        v.push_back(args[++i]);
      } else {
        std::size_t n = 0;
        while (i + 1 < args.size() && !(args[i + 1].size() > 1 && args[i + 1][0] == '-')) {
          v.push_back(args[++i]);
          ++n;
        }
        if (n == 0) throw UsageError("option '" + a + "' needs at least one value");
      }
      continue;
    }
    if (o.positional.size() >= max_positional) {
      throw UsageError("unexpected argument '" + a + "'");
    }
    o.positional.push_back(a);
  }
  return o;
}

std::optional<int> parse_command(std::string_view command, const char* help, Options& out,
                                 const std::vector<std::string>& args,
                                 const std::vector<OptionSpec>& specs, std::size_t max_positional) {
  try {
    out = parse_options(args, specs, max_positional);
  } catch (const UsageError& e) {
    std::cerr << "pointdriver " << command << ": " << e.what() << '\n' << help;
    return 1;
  }
  if (out.help) {
    std::cout << help;
    return 0;
  }
  return std::nullopt;
}

}  // namespace impact::pointdriver
