#pragma once
// The io/ tools every writer of output/ uses, named once for motostab::output: CSV tables and numbers as
// text (17 significant digits by default), files written completely or not at all, gnuplot quoting and
// rendering (script + png + svg), JSON with every number checked finite.
#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/json_text.h"
#include "io/plot.h"

namespace motostab::output {

using io::CsvWriter;
using io::formatJson;
using io::formatNumber;
using io::gnuplotQuote;
using io::gnuplotText;
using io::renderGnuplot;
using io::writeFileAtomically;

}  // namespace motostab::output
