#pragma once
// The study's verdicts on the seed paper's findings (studies/study_verdicts.h) as text: the report's
// section, the terminal summary, verdicts.json (pinned keys) and extended.yaml.
#include <filesystem>
#include <string>

#include "nlohmann/json.hpp"
#include "studies/study_verdicts.h"

namespace motostab::output {

/// report.md's section: per finding the paper's statement and tolerance beside motostab's figure and
/// verdict, then the extended motorcycle's; the causes diagnosis names for the disagreements (or the
/// candidates it cannot tell apart), the gain, and what the findings cannot settle.
std::string makeVerdictSection(const studies::StudyVerdicts& verdicts);

/// The few lines printed at the end of `motostab study`: one per finding, then the causes and the gain.
std::string makeVerdictSummary(const studies::StudyVerdicts& verdicts);

/// The verdicts.json document (keys pinned in docs/commands.md).
nlohmann::json makeVerdictJson(const studies::StudyVerdicts& verdicts);

/// Writes DIR/verdicts.json and DIR/extended.yaml (the scenario file `scenarioFile` with the
/// verdicts' extended overrides: a complete scenario that loads on its own).
void writeVerdictOutputs(const std::filesystem::path& dir, const std::string& scenarioFile,
                         const studies::StudyVerdicts& verdicts);

}  // namespace motostab::output
