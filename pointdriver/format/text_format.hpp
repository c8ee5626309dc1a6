// Number and CSV-cell formatting shared by the driver's messages, tables and CSV summaries (the
// per-step CSV rows use std::to_chars in csv_writer.cpp, which is faster).
#pragma once

#include <string>

namespace impact::pointdriver {

/// `v` with `significant` significant digits in printf's %g form (e.g. 1e-05, 0.0002, 1000).
std::string format_number(double v, int significant = 6);

/// A CSV cell (RFC 4180): quoted when it holds a comma, a quote or a newline, with quotes doubled
/// and newlines turned into spaces so that a row stays on one line.
std::string csv_cell(const std::string& s);

}  // namespace impact::pointdriver
