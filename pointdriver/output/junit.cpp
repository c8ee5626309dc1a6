#include "pointdriver/output/junit.hpp"

#include "support/atomic_file.hpp"

namespace impact::pointdriver {

namespace {

std::string escaped(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

void write_junit(const std::string& file, const std::string& suite,
                 const std::vector<JunitCase>& cases) {
  AtomicFile junit(file);
  std::ostream& out = junit.stream();
  int failures = 0;
  double seconds = 0.0;
  for (const JunitCase& c : cases) {
    failures += c.failure ? 1 : 0;
    seconds += c.seconds;
  }
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites tests=\"" << cases.size() << "\" failures=\"" << failures << "\">\n"
      << "  <testsuite name=\"" << escaped(suite) << "\" tests=\"" << cases.size()
      << "\" failures=\"" << failures << "\" errors=\"0\" time=\"" << seconds << "\">\n";
  for (const JunitCase& c : cases) {
    out << "    <testcase name=\"" << escaped(c.name) << "\" classname=\"" << escaped(c.classname)
        << "\" time=\"" << c.seconds << "\">\n";
    if (c.failure) out << "      <failure message=\"" << escaped(*c.failure) << "\"/>\n";
    if (!c.output.empty()) out << "      <system-out>" << escaped(c.output) << "</system-out>\n";
    out << "    </testcase>\n";
  }
  out << "  </testsuite>\n</testsuites>\n";
  junit.commit();
}

}  // namespace impact::pointdriver
