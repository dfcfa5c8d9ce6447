#pragma once
// Plots through gnuplot: each plot is a script beside its data, so users can restyle and re-run it.
#include <filesystem>
#include <string>

namespace motostab::io {

/// Writes DIR/NAME.gp and renders DIR/NAME.png and DIR/NAME.svg by running gnuplot in DIR.
/// `body` holds the gnuplot commands after the terminal and output are set (data files are named
/// relative to DIR). The images appear only when gnuplot succeeds. Throws std::runtime_error if
/// gnuplot is missing or fails, naming the script and quoting gnuplot's messages.
void renderGnuplot(const std::filesystem::path& dir, const std::string& name, const std::string& body);

/// Quotes a string for use inside a gnuplot single-quoted literal.
std::string gnuplotQuote(const std::string& text);

/// Quotes plain text (a mode, a file's column, a scenario name) for a title, label or key entry of a
/// terminal with enhanced text: the markup characters _ ^ @ & ~ { } \ are escaped, so that
/// "swingarm_torsion" prints as written rather than with a subscript.
std::string gnuplotText(const std::string& text);

}  // namespace motostab::io
