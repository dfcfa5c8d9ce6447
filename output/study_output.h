#pragma once
// Files written by `motostab study`: the seed paper's Figs. 9-12 with their data and scripts, and
// a markdown report setting each finding of seed sec. 4 against this model.
#include <filesystem>
#include <string>

#include "studies/study.h"
#include "studies/study_findings.h"
#include "studies/study_verdicts.h"

namespace motostab::output {

/// Writes DIR/study_modes.csv, DIR/weave_shapes.csv, fig09_root_locus, fig10_weave_real_part,
/// fig11_weave_real_part_halved, fig12_weave_shapes (.gp/.png/.svg), each variant's
/// eigenvalues.csv and summary.json under DIR/{nominal,halved}/VARIANT/, and DIR/report.md. With
/// `verdicts` also DIR/verdicts.json and DIR/extended.yaml (output/study_verdicts_output.h), the
/// scenario being `scenarioFile`.
void writeStudyOutputs(const std::filesystem::path& dir, const studies::StudyResult& study,
                       const studies::StudyFindings& findings, const studies::StudyOptions& options,
                       const studies::StudyVerdicts* verdicts = nullptr, const std::string& scenarioFile = "");

/// The markdown report alone, setting `findings` (studies::calcStudyFindings of `study`) against the paper;
/// with `verdicts`, their section first (the paper's findings one by one, the causes, the gain).
std::string makeStudyReport(const studies::StudyResult& study, const studies::StudyFindings& findings,
                            const studies::StudyOptions& options, const studies::StudyVerdicts* verdicts = nullptr);

}  // namespace motostab::output
