#pragma once
// Reads a CSV whose cells may be text (eigenvalues.csv has a `mode` column), for tests that check the
// files motostab writes: header, rows of cells, and numbers parsed strictly ("nan" allowed).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/csv.h"

struct TextCsv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// Index of a column, -1 if absent.
  int find(const std::string& name) const {
    for (size_t j = 0; j < header.size(); ++j)
      if (header[j] == name) return static_cast<int>(j);
    return -1;
  }
};

/// Every line split at commas; the first is the header. Throws if a row's width differs from the header's.
inline TextCsv readTextCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  TextCsv t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto cells = motostab::io::splitFields(line, ',');
    if (t.header.empty()) {
      t.header = cells;
    } else {
      if (cells.size() != t.header.size()) throw std::runtime_error(path.string() + ": ragged row: " + line);
      t.rows.push_back(cells);
    }
  }
  return t;
}

/// The whole cell as a double ("nan" gives NaN); throws on anything else.
inline double parseCell(const std::string& cell) {
  if (cell == "nan" || cell == "-nan") return std::nan("");
  size_t used = 0;
  const double v = std::stod(cell, &used);
  if (used != cell.size()) throw std::runtime_error("not a number: '" + cell + "'");
  return v;
}
