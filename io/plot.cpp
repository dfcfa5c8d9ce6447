#include "io/plot.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/atomic_file.h"

namespace motostab::io {

std::string gnuplotQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string gnuplotText(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    if (std::string("_^@&~{}\\").find(c) != std::string::npos) escaped += '\\';
    escaped += c;
  }
  return gnuplotQuote(escaped);
}

namespace {
std::string shellQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

void renderGnuplot(const std::filesystem::path& dir, const std::string& name, const std::string& body) {
  const std::string script =
      "# Made by motostab. Restyle and re-run with: gnuplot " + name + ".gp\n"
      "if (!exists('outstem')) outstem = " + gnuplotQuote(name) + "\n"
      "do for [ext in 'png svg'] {\n"
      "  if (ext eq 'png') { set terminal pngcairo size 1000,700 enhanced font ',11' }\n"
      "  else { set terminal svg size 1000,700 dynamic enhanced font 'Helvetica,12' }\n"
      "  set output outstem.'.'.ext\n" +
      body +
      "\n  unset output\n}\n";
  writeFileAtomically(dir / (name + ".gp"), script);
  const std::string stem = "." + name + ".rendering";
  const std::string cmd = "cd " + shellQuote(dir.string()) + " && gnuplot -e \"outstem='" + stem + "'\" " +
                          shellQuote(name + ".gp") + " 2>" + shellQuote(stem + ".log");
  const int rc = std::system(cmd.c_str());
  if (rc != 0) {  // the log's text, not its path: the folder is a temporary one, removed on the error
    std::ifstream log(dir / (stem + ".log"));
    std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    if (text.size() > 2000) text = "..." + text.substr(text.size() - 2000);
    throw std::runtime_error("gnuplot failed on the plot script " + name + ".gp" +
                             (text.empty() ? std::string(" (is gnuplot installed?)") : ":\n" + text));
  }
  for (const char* ext : {".png", ".svg"})
    std::filesystem::rename(dir / (stem + ext), dir / (name + ext));
  std::filesystem::remove(dir / (stem + ".log"));
}

}  // namespace motostab::io
