#pragma once
// Per component (mode part or response signal) summaries of a prediction's residuals for the report:
// the mean raw residual, the RMS of the normalised residuals the likelihood sees (an eigenvalue row's
// (measured - predicted) / sigma; a response signal's prewhitened residuals over their innovation sigma,
// noise_model.h eq. 1, so that an AR noise's correlation does not inflate it: about 1 where the model
// fits to the noise), the trend of eigenvalue residuals with speed, and a response signal's VAF.
#include <vector>

#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"

namespace motostab::diagnosis {

/// One entry per component of `problem`, normalised with the noise `problem` carries.
std::vector<ComponentResidual> summariseResiduals(const FitProblem& problem, const Prediction& p);

/// The normalised residuals the likelihood sees (FitProblem::calcResiduals), per observation.
std::vector<double> calcWhitenedResiduals(const FitProblem& problem, const Prediction& p);

}  // namespace motostab::diagnosis
